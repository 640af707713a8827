// `tessera regmap surface`: the JSON keys of the issue, the PLY's integer face property "tile",
// the GLB's "_TILE" attribute and extras, the base option, exit code 2 for bad input.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <set>

#include "cli_run.h"
#include "mesh/readers.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::run_cli;

// The JSON chunk of a GLB file.
nlohmann::json glb_json(const std::string& path) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(path, Limits());
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + length);
}

TEST(RegmapSurfaceCli, JsonAndPlyOfR24) {
  const std::string ply = test::temp_path("r24_surface.ply");
  const auto r = run_cli("regmap surface R2.4 -o '" + ply + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["genus"], 5);
  EXPECT_EQ(j["euler_characteristic"], -8);
  EXPECT_EQ(j["quarter_tubes"], 20);
  EXPECT_EQ(j["closed"], true);
  EXPECT_EQ(j["oriented"], true);
  EXPECT_EQ(j["relations_hold"], true);
  EXPECT_TRUE(j["self_intersections"].is_number_unsigned());
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
  const Mesh mesh = read_mesh_file(ply, Limits());
  ASSERT_EQ(mesh.face_attributes.count("tile"), 1u);
  const auto& tile = mesh.face_attributes.at("tile");
  EXPECT_EQ(std::set<std::int32_t>(tile.begin(), tile.end()).size(), 20u);
  EXPECT_EQ(mesh.face_count(), j["faces"].get<std::size_t>());
}

TEST(RegmapSurfaceCli, GlbCarriesTilesAndFigures) {
  const std::string glb = test::temp_path("r31_surface.glb");
  const auto r = run_cli("regmap surface R3.1 -o '" + glb + "' --no-self-intersections --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(nlohmann::json::parse(r.out)["self_intersections"].is_null());
  const nlohmann::json gltf = glb_json(glb);
  const auto& attributes = gltf["meshes"][0]["primitives"][0]["attributes"];
  EXPECT_TRUE(attributes.contains("_TILE"));
  EXPECT_TRUE(attributes.contains("COLOR_0"));
  EXPECT_EQ(gltf["scenes"][0]["extras"]["map"], "R3.1");
  EXPECT_EQ(gltf["scenes"][0]["extras"]["surface"]["genus"], 84 - 24 + 1);
  EXPECT_EQ(gltf["scenes"][0]["extras"]["surface"]["quarter_tubes"], 336);
}

TEST(RegmapSurfaceCli, BadInputExitsWithTwo) {
  for (const char* args :
       {"regmap surface", "regmap surface R2.4 --base cube", "regmap surface R2.4 --smoothness 1",
        "regmap surface R2.4 --tube-radius -1", "regmap surface R999.1",
        "regmap surface R3.1 --max-faces 100", "regmap surface R2.4 -o out.xyz"}) {
    const auto r = run_cli(args, true);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("tessera"), std::string::npos) << args;
  }
}

TEST(RegmapSurfaceCli, Help) {
  const auto r = run_cli("regmap surface --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--base"), std::string::npos);
  EXPECT_NE(run_cli("regmap --help").out.find("surface <map>"), std::string::npos);
}

}  // namespace
}  // namespace tessera
