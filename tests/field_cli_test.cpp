// tessera field and tessera param on generated meshes: JSON keys, Poincare-Hopf, the OBJ with
// per-corner vt, field files, exit codes.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "export/writers.h"
#include "mesh/shapes.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::quoted;
using test::run_cli;
using test::temp_path;
using test::write_temp_file;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void expect_singularity_keys(const nlohmann::json& json, long chi) {
  EXPECT_EQ(json["euler_characteristic"], chi);
  EXPECT_EQ(json["index_sum"].get<double>(), static_cast<double>(chi));
  double sum = 0;
  for (const auto& s : json["singularities"]) {
    const double index = s["index"].get<double>();
    EXPECT_EQ(s["valence"].get<int>(), 4 - static_cast<int>(4 * index));
    EXPECT_TRUE(s["vertex"].is_number_unsigned());
    sum += index;
  }
  EXPECT_EQ(sum, static_cast<double>(chi));
}

TEST(CliField, PrintsSingularitiesAsJson) {
  const std::string path = write_temp_file("double_torus.obj", write_obj(double_torus(2)));
  const auto result = run_cli("field --json " + quoted(path));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const auto json = nlohmann::json::parse(result.out);
  expect_singularity_keys(json, -2);
  EXPECT_FALSE(json["singularities"].empty());
  const auto text = run_cli("field --align curvature --sharp 50 " + quoted(path));
  ASSERT_EQ(text.exit_code, 0) << text.out;
  EXPECT_NE(text.out.find("Poincare-Hopf holds"), std::string::npos) << text.out;
}

TEST(CliField, ReadsAFieldFile) {
  const Mesh mesh = icosphere(1);
  const std::string mesh_path = write_temp_file("sphere.obj", write_obj(mesh));
  // Every face's direction along its first edge: some field of index sum 2.
  std::string rawfield = "1 " + std::to_string(mesh.face_count()) + "\n";
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto v = mesh.face(f);
    const Eigen::Vector3d d = mesh.positions[v[1]] - mesh.positions[v[0]];
    rawfield +=
        std::to_string(d.x()) + " " + std::to_string(d.y()) + " " + std::to_string(d.z()) + "\n";
  }
  const std::string field_path = write_temp_file(
      "sphere.rawfield", std::vector<std::uint8_t>(rawfield.begin(), rawfield.end()));
  const auto result =
      run_cli("field --json " + quoted(mesh_path) + " --field " + quoted(field_path));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  expect_singularity_keys(nlohmann::json::parse(result.out), 2);
}

TEST(CliField, BadInputExitsWithTwo) {
  const std::string mesh_path = write_temp_file("sphere.obj", write_obj(icosphere(1)));
  const std::string field_path = write_temp_file("short.rawfield", test::bytes_of("1 1\n1 0 0\n"));
  auto result = run_cli("field " + quoted(mesh_path) + " --field " + quoted(field_path), true);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.out.find("faces"), std::string::npos) << result.out;
  result = run_cli("field " + quoted(mesh_path) + " --align diagonal", true);
  EXPECT_EQ(result.exit_code, 2);
  result = run_cli("field " + quoted(mesh_path) + " --align curvature --field x.rawfield", true);
  EXPECT_EQ(result.exit_code, 2);
  result = run_cli("param " + quoted(mesh_path) + " --h -1", true);
  EXPECT_EQ(result.exit_code, 2);
  result = run_cli("field", true);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(run_cli("field --help").exit_code, 0);
  EXPECT_EQ(run_cli("param --help").exit_code, 0);
}

TEST(CliParam, PrintsFiguresAndWritesUv) {
  const Mesh mesh = double_torus(2);
  const std::string path = write_temp_file("double_torus.obj", write_obj(mesh));
  const std::string out = temp_path("param.obj");
  const auto result = run_cli("param --json " + quoted(path) + " -o " + quoted(out));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const auto json = nlohmann::json::parse(result.out);
  expect_singularity_keys(json, -2);
  EXPECT_EQ(json["flipped_outside_singular_rings"], 0);
  EXPECT_LE(json["flipped_triangles"].get<int>(), json["flipped_before_injectivity"].get<int>());
  const auto& injectivity = json["injectivity"];
  EXPECT_LE(
      injectivity["unsolved_programs"].get<int>() + injectivity["skipped_programs"].get<int>(),
      injectivity["programs"].get<int>());
  if (json["flipped_before_injectivity"].get<int>() > 0)
    EXPECT_GT(injectivity["constrained_faces"].get<int>(), 0);
  EXPECT_LT(json["max_seam_error"].get<double>(), 1e-8);
  for (const char* step : {"field", "cut graph", "assembly", "solve", "injectivity"})
    EXPECT_TRUE(json["seconds"].contains(step)) << step;

  const std::string obj = read_text(out);
  std::size_t vt = 0, pos = 0;
  while ((pos = obj.find("\nvt ", pos)) != std::string::npos) ++vt, ++pos;
  EXPECT_EQ(vt, mesh.corner_count());
  const auto first = mesh.face(0);
  const std::string face = "\nf " + std::to_string(first[0] + 1) + "/1 " +
                           std::to_string(first[1] + 1) + "/2 " + std::to_string(first[2] + 1) +
                           "/3\n";
  EXPECT_NE(obj.find(face), std::string::npos) << face;
}

}  // namespace
}  // namespace tessera
