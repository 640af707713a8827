#include <gtest/gtest.h>

#include <chrono>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "export/writers.h"
#include "mesh/readers.h"
#include "mesh/shapes.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::bytes_of;
using test::quoted;
using test::run_cli;
using test::write_temp_file;

TEST(CliInfo, PrintsTheFixedJsonKeys) {
  const std::string path = write_temp_file("torus.obj", write_obj(torus(1.0, 0.3, 24, 12)));
  const auto result = run_cli("info --json " + quoted(path));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const auto json = nlohmann::json::parse(result.out);
  for (const char* key : {"vertices", "faces", "edges", "components", "boundary_loops", "genus",
                          "euler_characteristic", "manifold", "oriented", "bbox_diagonal",
                          "warnings", "face_sizes", "bbox_min", "bbox_max"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["vertices"], 288);
  EXPECT_EQ(json["faces"], 576);
  EXPECT_EQ(json["genus"], 1);
  EXPECT_EQ(json["euler_characteristic"], 0);
  EXPECT_EQ(json["face_sizes"]["3"], 576);
  EXPECT_EQ(json["manifold"], true);
  EXPECT_EQ(json["oriented"], true);
  EXPECT_TRUE(json["warnings"].empty());
}

TEST(CliInfo, ReportsRepairsAsWarnings) {
  // Open cylinder written as OBJ with one face flipped: fixed and reported, still exit 0.
  Mesh mesh = open_cylinder(1, 1, 8, 2);
  std::swap(mesh.face_vertices[1], mesh.face_vertices[2]);
  const std::string path = write_temp_file("flipped.obj", write_obj(mesh));
  const auto result = run_cli("info --json " + quoted(path));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["oriented"], false);
  EXPECT_EQ(json["boundary_loops"], 2);
  ASSERT_EQ(json["warnings"].size(), 1u);
  EXPECT_NE(json["warnings"][0].get<std::string>().find("1 faces flipped"), std::string::npos);
}

TEST(CliInfo, WeldsCracksAndKeepsApartPartsTouchingAtAVertex) {
  const std::string cracked =
      write_temp_file("cracked.obj", write_obj(test::torus_cracked_at_seam(24, 12)));
  const auto welded = run_cli("info --json " + quoted(cracked));
  ASSERT_EQ(welded.exit_code, 0) << welded.out;
  const auto closed = nlohmann::json::parse(welded.out);
  EXPECT_EQ(closed["genus"], 1);
  EXPECT_EQ(closed["boundary_loops"], 0);
  ASSERT_EQ(closed["warnings"].size(), 1u);
  EXPECT_NE(closed["warnings"][0].get<std::string>().find("12 duplicate vertices welded"),
            std::string::npos);

  // Two triangles whose tips are 1e-9 apart: welded, they would pinch.
  const Mesh tips =
      triangle_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1e-9, 0, 0}, {-1, 0, 0}, {-1, -1, 0}},
                    {{0, 1, 2}, {3, 4, 5}});
  const std::string path = write_temp_file("tips.obj", write_obj(tips));
  const auto result = run_cli("info --json " + quoted(path));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["components"], 2);
  EXPECT_NE(json["warnings"].dump().find("1 groups of near-duplicate vertices kept apart"),
            std::string::npos)
      << json["warnings"].dump();
}

TEST(CliInfo, HelpAndUsage) {
  EXPECT_EQ(run_cli("info --help").exit_code, 0);
  EXPECT_EQ(run_cli("convert --help").exit_code, 0);
  EXPECT_EQ(run_cli("info").exit_code, 2);
  EXPECT_EQ(run_cli("info a.obj --bogus").exit_code, 2);
  const auto missing = run_cli("info /nonexistent/mesh.obj", true);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.out.find("cannot open /nonexistent/mesh.obj"), std::string::npos)
      << missing.out;
}

// Each bad file: exit code 2, a message naming the file and the place, well under 2 s.
TEST(CliInfo, BadInputGivesExitCodeTwoAndASpecificMessage) {
  std::vector<std::uint8_t> truncated_stl = write_stl(icosphere(1));
  truncated_stl.resize(truncated_stl.size() - 10);
  const std::vector<std::pair<std::string, std::vector<std::uint8_t>>> cases = {
      {"empty.obj", {}},
      {"index.obj", bytes_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")},
      {"nan.off", bytes_of("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")},
      {"huge.off", bytes_of("OFF\n3 10000000000 0\n")},
      {"cut.stl", truncated_stl},
      {"fin.obj",
       bytes_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n")},
      {"flat.obj", bytes_of("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")},
  };
  const std::vector<std::string> expected = {
      "empty", ":4:", "vertex 1", "--max-faces", "truncated", "non-manifold edge", "zero area"};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string path = write_temp_file(cases[i].first, cases[i].second);
    const auto start = std::chrono::steady_clock::now();
    const auto result = run_cli("info " + quoted(path), true);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
    EXPECT_EQ(result.exit_code, 2) << cases[i].first << ": " << result.out;
    EXPECT_NE(result.out.find(cases[i].first), std::string::npos) << result.out;
    EXPECT_NE(result.out.find(expected[i]), std::string::npos) << result.out;
  }
}

TEST(CliConvert, ObjToGlbToObjKeepsTheMesh) {
  Mesh mesh = double_torus(2);
  for (auto& p : mesh.positions) p = 37.5 * p + Eigen::Vector3d(-3, 1e3, 7);
  const std::string obj = write_temp_file("in.obj", write_obj(mesh));
  const std::string glb = test::temp_path("mid.glb");
  const std::string back = test::temp_path("out.obj");
  ASSERT_EQ(run_cli("convert " + quoted(obj) + " " + quoted(glb)).exit_code, 0);
  ASSERT_EQ(run_cli("convert " + quoted(glb) + " " + quoted(back)).exit_code, 0);
  const Mesh result = read_mesh_file(back, {});
  test::expect_same_mesh(mesh, result, 1e-6);
}

TEST(CliConvert, PlyKeepsPolygonsAndRefusesUnknownExtensions) {
  const std::string obj = write_temp_file("quads.obj", write_obj(quad_torus(1, 0.3, 12, 6)));
  const std::string ply = test::temp_path("quads.ply");
  ASSERT_EQ(run_cli("convert --ascii " + quoted(obj) + " " + quoted(ply)).exit_code, 0);
  const Mesh back = read_mesh_file(ply, {});
  EXPECT_EQ(back.face_count(), 72u);
  EXPECT_EQ(back.face_size(0), 4u);
  const auto bad = run_cli("convert " + quoted(obj) + " out.xyz", true);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.out.find(".obj, .ply, .glb"), std::string::npos) << bad.out;
}

}  // namespace
}  // namespace tessera
