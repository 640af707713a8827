// `tessera regmap info|catalog`: JSON output, catalog names and files, and exit code 2 with a
// clear message for bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::run_cli;

std::string write_temp(const std::string& name, const std::string& text) {
  return test::write_temp_file(name, test::bytes_of(text));
}

TEST(RegmapCli, InfoJsonOfTheKleinQuartic) {
  const auto r = run_cli("regmap info R3.1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["name"], "R3.1");
  EXPECT_EQ(j["p"], 3);
  EXPECT_EQ(j["q"], 7);
  EXPECT_EQ(j["order"], 336);
  EXPECT_EQ(j["vertices"], 24);
  EXPECT_EQ(j["edges"], 84);
  EXPECT_EQ(j["faces"], 56);
  EXPECT_EQ(j["genus"], 3);
  EXPECT_EQ(j["petrie"], 8);
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
}

TEST(RegmapCli, InfoOfADualAndOfAFile) {
  const auto dual = nlohmann::json::parse(run_cli("regmap info \"R2.4'\" --json").out);
  EXPECT_EQ(dual["vertices"], 2);
  EXPECT_EQ(dual["faces"], 1);
  const std::string cube = write_temp(
      "cube.txt",
      "Cube : Type {4,3}_6 Order 48\n[ T^2, R^4, S^3, (R * S)^2, (R * T)^2, (S * T)^2 ]\n");
  const auto r = run_cli("regmap info '" + cube + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["name"], "Cube");
  EXPECT_EQ(j["vertices"], 8);
  EXPECT_EQ(j["genus"], 0);
}

TEST(RegmapCli, BadInputExitsWithTwo) {
  const std::string bad = write_temp("bad.txt", "Type {3,7}\n[ R^3, X ]\n");
  const std::string infinite =
      write_temp("infinite.txt", "Type {3,7}\n[ T^2, (R * S)^2, (R * T)^2, (S * T)^2 ]\n");
  const std::string lying = write_temp(
      "lying.txt", "Type {4,3} Order 50\n[ T^2, R^4, S^3, (R * S)^2, (R * T)^2, (S * T)^2 ]\n");
  const std::string cube_like =
      write_temp("cube_like.txt", "Type {4,3}\n[ T^2, R^4, S^3, (R * S)^2 ]\n");
  const struct {
    std::string args;
    const char* message;
  } cases[] = {
      {"regmap info R9.99", "no map named 'R9.99'"},
      {"regmap info nothing-here", "neither a presentation file nor a catalog name"},
      {"regmap info '" + bad + "'", "2:8: unknown generator 'X'"},
      {"regmap info '" + infinite + "' --max-cosets 20000", "--max-cosets"},
      {"regmap info '" + lying + "'", "states order 50"},
      {"regmap info", "takes one map"},
      {"regmap info R3.1 --max-cosets lots", "--max-cosets expects a non-negative integer"},
      {"regmap catalog --type 3", "--type expects p,q"},
      {"regmap catalog --colour", "unknown option '--colour'"},
      {"regmap frobnicate", "unknown subcommand"},
      {"regmap tiling R3.1 -o /dev/null --max-triangles 100", "--max-triangles"},
      {"regmap info '" + cube_like + "' --max-file-bytes 10", "--max-file-bytes"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli(c.args, true);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
  }
}

TEST(RegmapCli, CatalogFollowsTesseraDataDir) {
  const auto r = run_cli("regmap info R3.1", true);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const auto moved = run_cli("regmap info R3.1", true, "TESSERA_DATA_DIR=/nonexistent");
  EXPECT_EQ(moved.exit_code, 2) << moved.out;
  EXPECT_NE(moved.out.find("/nonexistent/regmaps/catalog_g2-101.tsv"), std::string::npos)
      << moved.out;
  EXPECT_NE(moved.out.find("set TESSERA_DATA_DIR"), std::string::npos) << moved.out;
}

TEST(RegmapCli, CatalogFilters) {
  const auto genus2 = nlohmann::json::parse(run_cli("regmap catalog --genus 2 --json").out);
  ASSERT_EQ(genus2.size(), 6u);
  EXPECT_EQ(genus2[3]["name"], "R2.4");
  const auto heptagons = nlohmann::json::parse(run_cli("regmap catalog --type 7,3 --json").out);
  ASSERT_FALSE(heptagons.empty());
  EXPECT_EQ(heptagons[0]["name"], "R3.1'");
  for (const auto& row : heptagons) {
    EXPECT_EQ(row["p"], 7);
    EXPECT_EQ(row["q"], 3);
  }
  const auto all = run_cli("regmap catalog");
  EXPECT_EQ(all.exit_code, 0);
  EXPECT_NE(all.out.find("R101."), std::string::npos);
}

TEST(RegmapCli, TilingWritesTheSvgAndReportsThePolygon) {
  const auto svg = std::filesystem::temp_directory_path() / "tessera_regmap_cli_r31.svg";
  std::filesystem::remove(svg);
  const auto r = run_cli("regmap tiling R3.1 -o '" + svg.string() + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["geometry"], "hyperbolic");
  EXPECT_EQ(j["triangles"], 336);
  EXPECT_EQ(j["polygon_euler"], 1);
  EXPECT_EQ(j["boundary_cycles"], 1);
  EXPECT_GT(j["boundary_pairs"].get<int>(), 0);
  ASSERT_TRUE(std::filesystem::exists(svg));
  EXPECT_GT(std::filesystem::file_size(svg), 10000u);
}

TEST(RegmapCli, TilingNeedsAWritableOutput) {
  const auto missing = run_cli("regmap tiling R2.4", true);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.out.find("needs -o FILE.svg"), std::string::npos) << missing.out;
  const auto unwritable = run_cli("regmap tiling R2.4 -o /nonexistent-dir/t.svg", true);
  EXPECT_EQ(unwritable.exit_code, 2);
  EXPECT_NE(unwritable.out.find("cannot write"), std::string::npos) << unwritable.out;
}

TEST(RegmapCli, HelpEverywhere) {
  for (const char* args :
       {"regmap --help", "regmap info --help", "regmap catalog --help", "regmap tiling --help"}) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_NE(r.out.find("usage: tessera regmap"), std::string::npos) << args;
  }
}

}  // namespace
}  // namespace tessera
