// tessera remesh on generated meshes: the JSON figures of issue 39 for a closed quad mesh with the
// layout's patches, the PLY with an integer face property 'patch', --quads changing the count, and
// exit code 2 with a message for bad options.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "export/writers.h"
#include "mesh/load.h"
#include "mesh/shapes.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::quoted;
using test::run_cli;
using test::temp_path;
using test::write_temp_file;

nlohmann::json remesh_json(const std::string& arguments) {
  const auto result = run_cli("remesh --json " + arguments);
  EXPECT_EQ(result.exit_code, 0) << result.out;
  return result.exit_code == 0 ? nlohmann::json::parse(result.out) : nlohmann::json::object();
}

TEST(CliRemesh, WritesAClosedQuadMeshWithTheLayoutsPatches) {
  const std::string path = write_temp_file("remesh_torus.obj", write_obj(double_torus(3)));
  const std::string ply = temp_path("remesh_torus.ply");
  const auto json = remesh_json(quoted(path) + " --alpha 10 --quads 1200 -o " + quoted(ply));
  for (const char* key : {"quads", "vertices", "irregular_vertices", "patches",
                          "min_scaled_jacobian", "mean_scaled_jacobian", "max_angle_deviation",
                          "mean_angle_deviation", "flipped_quads", "seconds"})
    ASSERT_TRUE(json.contains(key)) << key;
  EXPECT_NEAR(json["quads"].get<double>(), 1200, 180);
  EXPECT_EQ(json["flipped_quads"], 0);
  EXPECT_GT(json["min_scaled_jacobian"].get<double>(), 0);
  EXPECT_EQ(json["boundary_edges"], 0);
  EXPECT_EQ(json["euler_characteristic"], -2);
  EXPECT_EQ(json["input_euler_characteristic"], -2);
  for (const char* step : {"layout", "integer lengths", "patch maps", "check"})
    EXPECT_TRUE(json["seconds"].contains(step)) << step;

  const LoadedMesh quads = load_mesh_file(ply);
  EXPECT_EQ(quads.mesh.face_count(), json["quads"].get<std::size_t>());
  EXPECT_EQ(quads.mesh.corner_count(), 4 * quads.mesh.face_count());
  const auto& patch = quads.mesh.face_attributes.at("patch");
  EXPECT_EQ(*std::min_element(patch.begin(), patch.end()), 0);
  EXPECT_EQ(*std::max_element(patch.begin(), patch.end()) + 1, json["patches"].get<int>());
}

TEST(CliRemesh, WritesGlbWithThePatchAttribute) {
  const std::string path = write_temp_file("remesh_glb.obj", write_obj(icosphere(3)));
  const std::string glb = temp_path("remesh_quads.glb");
  remesh_json(quoted(path) + " --alpha 10 --quads 400 -o " + quoted(glb));
  const std::vector<std::uint8_t> bytes = read_file_bytes(glb, Limits{});
  const std::string text(bytes.begin(), bytes.end());
  EXPECT_EQ(text.substr(0, 4), "glTF");
  EXPECT_NE(text.find("_PATCH"), std::string::npos);
}

TEST(CliRemesh, QuadsOptionChangesTheCount) {
  const std::string path = write_temp_file("remesh_sphere.obj", write_obj(icosphere(3)));
  const std::string obj = temp_path("remesh_sphere_quads.obj");
  const auto few = remesh_json(quoted(path) + " --alpha 10 --quads 300 -o " + quoted(obj));
  const auto many = remesh_json(quoted(path) + " --alpha 10 --quads 3000 -o " + quoted(obj));
  EXPECT_NEAR(few["quads"].get<double>(), 300, 60);
  EXPECT_NEAR(many["quads"].get<double>(), 3000, 300);
  EXPECT_EQ(few["patches"], many["patches"]);
  // Finer quads follow the sphere closer.
  EXPECT_LT(many["hausdorff_relative"].get<double>(), few["hausdorff_relative"].get<double>());
  EXPECT_LT(many["hausdorff_relative"].get<double>(), 0.01);
}

TEST(CliRemesh, SmoothKeepsTheMeshAndAddsItsStep) {
  const std::string path = write_temp_file("remesh_smooth.obj", write_obj(icosphere(3)));
  const std::string obj = temp_path("remesh_smooth_quads.obj");
  const auto plain = remesh_json(quoted(path) + " --alpha 10 --quads 600 -o " + quoted(obj));
  const auto smooth =
      remesh_json(quoted(path) + " --alpha 10 --quads 600 --smooth -o " + quoted(obj));
  EXPECT_EQ(smooth["quads"], plain["quads"]);
  EXPECT_EQ(smooth["irregular_vertices"], plain["irregular_vertices"]);
  EXPECT_EQ(smooth["flipped_quads"], 0);
  EXPECT_GE(smooth["min_scaled_jacobian"].get<double>(),
            std::min(plain["min_scaled_jacobian"].get<double>(), 0.5) - 1e-12);
  EXPECT_TRUE(smooth["seconds"].contains("smoothing"));
  EXPECT_FALSE(plain["seconds"].contains("smoothing"));
}

TEST(CliRemesh, BadOptionsExitWithTwo) {
  const std::string path = write_temp_file("remesh_bad.obj", write_obj(icosphere(2)));
  const std::string obj = temp_path("remesh_bad_out.obj");
  for (const std::string& arguments :
       {"remesh " + quoted(path), "remesh " + quoted(path) + " --quads 0 -o " + quoted(obj),
        "remesh " + quoted(path) + " --quads 10 --edge-length 1 -o " + quoted(obj),
        "remesh " + quoted(path) + " -o out.xyz", "remesh --quads 10 -o " + quoted(obj),
        "remesh " + quoted(path) + " --smooth --smooth-rounds x -o " + quoted(obj)}) {
    const auto result = run_cli(arguments, true);
    EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.out;
    EXPECT_NE(result.out.find("error"), std::string::npos) << arguments;
  }
}

}  // namespace
}  // namespace tessera
