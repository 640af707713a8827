// tessera optimize-quads (issue 40): JSON keys, the output's patch property, bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "export/writers.h"
#include "mesh/connectivity.h"
#include "mesh/readers.h"
#include "mesh/shapes.h"
#include "mesh_test_util.h"
#include "quadmesh/base_complex.h"
#include "quadmesh_test_util.h"

namespace tessera {
namespace {

std::string torus_file(const std::string& name) {
  Mesh torus = quad_torus(3, 1, 24, 12);
  test::rotate_quad_edge(torus, 12 * 5 + 4, 12 * 6 + 4);
  test::rotate_quad_edge(torus, 12 * 17 + 5, 12 * 18 + 5);
  return test::write_temp_file(name, write_obj(torus));
}

TEST(QuadmeshCli, JsonHasTheKeysOfIssue40AndThePlyItsPatches) {
  const std::string in = torus_file("torus.obj");
  const std::string out = test::temp_path("layout.ply");
  const test::CliResult r = test::run_cli("optimize-quads " + test::quoted(in) +
                                          " --alpha 0 --json -o " + test::quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json json = nlohmann::json::parse(r.out);
  for (const char* key : {"singularities", "base_complex_patches", "patches", "angle_rsd",
                          "graph_edges", "conflicts", "matching_status", "seconds"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["singularities"], 8);
  EXPECT_EQ(json["base_complex_patches"], 16);
  EXPECT_EQ(json["patches"], 8);
  EXPECT_EQ(json["valid"], true);
  EXPECT_EQ(json["matching_status"], "optimal");
  const std::vector<std::uint8_t> bytes = read_file_bytes(out, Limits());
  const Mesh written = read_ply(bytes, out, Limits());
  const std::vector<std::int32_t>& patch = written.face_attributes.at("patch");
  ASSERT_EQ(patch.size(), written.face_count());
  EXPECT_EQ(*std::max_element(patch.begin(), patch.end()), 7);
}

// The optimized layout as a quad mesh of its own (Ch. 8): its trivial base complex is the layout.
TEST(QuadmeshCli, RemeshedQuadMeshHasTheOptimizedLayoutAsItsBaseComplex) {
  const std::string in = torus_file("torus.obj");
  const std::string out = test::temp_path("remeshed.obj");
  const test::CliResult r = test::run_cli("optimize-quads " + test::quoted(in) +
                                          " --alpha 0 --json --remesh " + test::quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["patches"], 8);
  EXPECT_EQ(json["remeshed_irregular_vertices"], 8);
  const Mesh remeshed = read_obj(read_file_bytes(out, Limits()), out, Limits());
  const quadmesh::BaseComplex b =
      quadmesh::trivial_base_complex(remeshed, build_connectivity(remeshed));
  EXPECT_EQ(b.patch_count, 8u);
  EXPECT_TRUE(b.check.valid());
}

TEST(QuadmeshCli, NoDiagonalsIsReported) {
  const std::string in = torus_file("torus.obj");
  const test::CliResult r =
      test::run_cli("optimize-quads " + test::quoted(in) + " --no-diagonals --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["diagonals"], false);
  EXPECT_EQ(json["diagonal_edges"], 0);
  EXPECT_EQ(json["valid"], true);
}

TEST(QuadmeshCli, TrianglesAreRefusedWithWhereAndSplitOnRequest) {
  Mesh mesh = test::flat_quad_grid(3, 3);
  mesh.add_vertex({4, 0, 0});
  mesh.add_face({12, 16, 13});  // a triangle beside the grid's edge (3, 0)-(3, 1)
  const std::string in = test::write_temp_file("mixed.obj", write_obj(mesh));
  const test::CliResult refused = test::run_cli("optimize-quads " + test::quoted(in), true);
  EXPECT_EQ(refused.exit_code, 2) << refused.out;
  EXPECT_NE(refused.out.find("1 of 10 faces are not quads (1 triangles"), std::string::npos)
      << refused.out;
  EXPECT_NE(refused.out.find("face 9 (3 corners"), std::string::npos) << refused.out;
  const test::CliResult split =
      test::run_cli("optimize-quads " + test::quoted(in) + " --split --json");
  ASSERT_EQ(split.exit_code, 0) << split.out;
  const nlohmann::json json = nlohmann::json::parse(split.out);
  EXPECT_EQ(json["quads"], 4 * 9 + 3);
  EXPECT_EQ(json["valid"], true);
}

// glTF holds triangles only: a quad mesh converted to GLB comes back as its quads.
TEST(QuadmeshCli, GlbOfAQuadMeshIsJoinedBackIntoQuads) {
  const std::string in = torus_file("torus.obj");
  const std::string glb = test::temp_path("torus.glb");
  ASSERT_EQ(test::run_cli("convert " + test::quoted(in) + " " + test::quoted(glb)).exit_code, 0);
  const test::CliResult refused = test::run_cli("optimize-quads " + test::quoted(glb), true);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.out.find("--join-triangles"), std::string::npos) << refused.out;
  const test::CliResult r =
      test::run_cli("optimize-quads " + test::quoted(glb) + " --join-triangles --alpha 0 --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["quads"], 24 * 12);
  EXPECT_EQ(json["base_complex_patches"], 16);
  EXPECT_EQ(json["patches"], 8);
}

TEST(QuadmeshCli, BadInputExitsWithTwo) {
  EXPECT_EQ(test::run_cli("optimize-quads").exit_code, 2);
  EXPECT_EQ(test::run_cli("optimize-quads /nonexistent/quads.obj").exit_code, 2);
  const std::string in = torus_file("torus.obj");
  EXPECT_EQ(test::run_cli("optimize-quads " + test::quoted(in) + " --alpha -1").exit_code, 2);
  EXPECT_EQ(test::run_cli("optimize-quads " + test::quoted(in) + " -o out.xyz").exit_code, 2);
  const std::string plain = test::write_temp_file("plain.obj", write_obj(quad_torus(3, 1, 12, 6)));
  const test::CliResult r = test::run_cli("optimize-quads " + test::quoted(plain), true);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("no irregular vertex"), std::string::npos) << r.out;
  EXPECT_EQ(test::run_cli("optimize-quads --help").exit_code, 0);
}

}  // namespace
}  // namespace tessera
