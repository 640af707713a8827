// `tessera regmap map`: the JSON keys of the issue, the PLY's integer face properties "face" and
// "tile" (F distinct faces), the GLB's edges and extras, and exit code 2 with a message naming
// what was tried when there is no pairing or the target does not fit.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "cli_run.h"
#include "mesh/geometry.h"
#include "mesh/readers.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::run_cli;

TEST(RegmapMapCli, JsonAndPlyOfR34OnItsTorusMap) {
  const std::string ply = test::temp_path("r34_mapped.ply");
  const auto r = run_cli("regmap map R3.4 --on '{4,4}_(1,1)' -o '" + ply + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["source"], "R3.4");
  EXPECT_EQ(j["target"], "{4,4}_(1,1)");
  EXPECT_EQ(j["genus"], 3);
  EXPECT_EQ(j["V"], 8);
  EXPECT_EQ(j["E"], 24);
  EXPECT_EQ(j["F"], 12);
  EXPECT_EQ(j["faces_are_disks"], true);
  EXPECT_EQ(j["closed"], true);
  EXPECT_TRUE(j["self_intersections"].is_number_unsigned());
  EXPECT_TRUE(j.contains("symmetries_verified"));
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
  const Mesh mesh = read_mesh_file(ply, Limits());
  ASSERT_EQ(mesh.face_attributes.count("face"), 1u);
  ASSERT_EQ(mesh.face_attributes.count("tile"), 1u);
  const auto& face = mesh.face_attributes.at("face");
  EXPECT_EQ(std::set<int>(face.begin(), face.end()).size(), 12u);
  const auto& tile = mesh.face_attributes.at("tile");
  EXPECT_EQ(std::set<int>(tile.begin(), tile.end()).size(), 16u);  // 4E of {4,4}_(1,1)
}

// An STL to print: in millimetres at the size asked, closed, and the print check in the JSON, with
// a wall thicker than the tubes named as the problem.
TEST(RegmapMapCli, StlToPrintIsScaledAndChecked) {
  const std::string stl = test::temp_path("r31_print.stl");
  const auto r = run_cli("regmap map R3.1 -o '" + stl + "' --print-size 80 --wall 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto print = nlohmann::json::parse(r.out)["print"];
  EXPECT_EQ(print["closed"], true);
  EXPECT_EQ(print["oriented"], true);
  EXPECT_EQ(print["self_intersections"], 0);
  EXPECT_EQ(print["printable"], true);
  const double thinnest = print["thinnest_mm"].get<double>();
  EXPECT_GT(thinnest, 1.0);
  const Mesh mesh = read_mesh_file(stl, Limits());
  const BoundingBox box = bounding_box(mesh);
  EXPECT_NEAR((box.max - box.min).maxCoeff(), 80.0, 1e-3);
  EXPECT_NEAR(box.min.z(), 0.0, 1e-3);

  const auto thin = run_cli("regmap map R3.1 -o '" + stl + "' --print-size 80 --wall " +
                            std::to_string(2 * thinnest));
  ASSERT_EQ(thin.exit_code, 0) << thin.out;
  EXPECT_NE(thin.out.find("not printable: the solid is thinner than"), std::string::npos)
      << thin.out;
  EXPECT_NE(thin.out.find("print it at least 16"), std::string::npos) << thin.out;  // 2 x 80

  const auto glb =
      run_cli("regmap map R3.1 -o '" + test::temp_path("r31.glb") + "' --wall 2", true);
  EXPECT_EQ(glb.exit_code, 2);
  EXPECT_NE(glb.out.find("--print-size and --wall are for an STL"), std::string::npos) << glb.out;
  const auto bad = run_cli("regmap map R3.1 -o '" + stl + "' --print-size 0", true);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.out.find("print size must be"), std::string::npos) << bad.out;
}

TEST(RegmapMapCli, PicksATargetOfTheGenusByItself) {
  const auto r = run_cli("regmap map R2.2 --json --no-self-intersections");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["genus"], 2);
  EXPECT_EQ(j["F"], j["expected"]["F"]);
  EXPECT_TRUE(j["self_intersections"].is_null());
}

// The Klein quartic has no reflection pairing (thesis Sec. 9.6); it is drawn through rotations.
TEST(RegmapMapCli, DrawsTheKleinQuarticOnTheTetrahedron) {
  const auto r = run_cli("regmap map R3.1 --json --no-self-intersections");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["target"], "Tetrahedron");
  EXPECT_EQ(j["pairing"]["kind"], "rotations");
  EXPECT_EQ(j["V"], 24);
  EXPECT_EQ(j["E"], 84);
  EXPECT_EQ(j["F"], 56);
  EXPECT_EQ(j["genus"], 3);
  EXPECT_EQ(j["faces_are_disks"], true);
}

TEST(RegmapMapCli, NoPairingOrAWrongTargetExitsWithTwo) {
  const auto none = run_cli("regmap map R3.1 --max-steps 1", true);
  EXPECT_EQ(none.exit_code, 2) << none.out;
  EXPECT_NE(none.out.find("no pairing, by reflections or by rotations, with"), std::string::npos)
      << none.out;
  EXPECT_NE(none.out.find("Tetrahedron"), std::string::npos) << none.out;
  EXPECT_NE(none.out.find("raise it"), std::string::npos) << none.out;
  for (const char* args : {"regmap map", "regmap map R3.4 --on Cube", "regmap map R3.4 --on Nope",
                           "regmap map R3.4 -o out.xyz", "regmap map R3.4 --subdivisions 500"}) {
    const auto r = run_cli(args, true);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out;
  }
}

// The batch over genus 3: every catalog map of genus 3 and its dual searched, the Klein quartic
// realized on the tetrahedron, the manifest's pairing one the drawing accepts.
TEST(RegmapRealizeCli, CountsAndManifestOfGenusThree) {
  const std::string manifest_path = test::temp_path("realizations_g3.json");
  const auto r = run_cli("regmap realize --genus 3 -o '" + manifest_path + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto counts = nlohmann::json::parse(r.out);
  EXPECT_GT(counts["maps"].get<int>(), 10);
  EXPECT_GE(counts["realized"].get<int>(), 5);
  EXPECT_EQ(counts["highest_genus"], 3);
  // Each map's pairings are drawn until one is right: those that were not are counted.
  EXPECT_TRUE(counts["pairings_drawn_wrong"].is_number_unsigned());
  std::ifstream in(manifest_path);
  const auto manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest["maps"].size(), counts["realized"].get<std::size_t>());
  bool klein = false;
  for (const auto& m : manifest["maps"]) {
    EXPECT_EQ(m["genus"], 3);
    EXPECT_TRUE(m["pairing"].contains("corners"));
    // Every chosen surface is built and searched for crossings (none at genus 3).
    EXPECT_TRUE(m["surface"]["base"].is_string());
    EXPECT_EQ(m["surface"]["self_intersections"], 0);
    if (m["source"] == "R3.1") klein = m["target"] == "Tetrahedron";
  }
  EXPECT_TRUE(klein);
  EXPECT_EQ(counts["self_intersection_free"], counts["realized"]);
  // Every map of the range is in the manifest with its figures, realized or not (the gallery's
  // cards): R3.1' (dual: V and F swapped) among them.
  EXPECT_EQ(manifest["maps"].size() + manifest["unrealized"].size(),
            counts["maps"].get<std::size_t>());
  bool dual = false;
  for (const auto& list : {manifest["maps"], manifest["unrealized"]}) {
    for (const auto& m : list) {
      EXPECT_EQ(m["genus"], 3);
      EXPECT_EQ(m["order"].get<int>(), 4 * m["E"].get<int>());
      if (m["source"] == "R3.1'") dual = m["p"] == 7 && m["q"] == 3 && m["V"] == 56 && m["F"] == 24;
    }
  }
  EXPECT_TRUE(dual);
  for (const char* args : {"regmap realize --genus 1", "regmap realize --genus 5..3",
                           "regmap realize --genus x", "regmap realize R3.1"}) {
    const auto bad = run_cli(args, true);
    EXPECT_EQ(bad.exit_code, 2) << args << "\n" << bad.out;
  }
}

TEST(RegmapMapCli, Help) {
  const auto r = run_cli("regmap map --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--on"), std::string::npos);
  EXPECT_NE(run_cli("regmap --help").out.find("map <map>"), std::string::npos);
}

}  // namespace
}  // namespace tessera
