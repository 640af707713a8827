// `tessera solve`: the JSON keys, every solver on both file forms, infeasible instances as answers,
// bad input and usage as exit code 2; `tessera layout --export-p1` writes the instance it solves.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "export/writers.h"
#include "matching/generate.h"
#include "matching/instance_file.h"
#include "matching/instance_json.h"
#include "matching/instance_lp.h"
#include "mesh/shapes.h"
#include "mesh_test_util.h"

namespace tessera::matching {
namespace {

using test::run_cli;
using test::temp_path;
using test::write_temp_file;

MatchingProblem instance() {
  PlantedSpec spec;
  spec.ports = 30;
  spec.virtual_ports = 2;
  spec.conflicts = 120;
  spec.seed = 5;
  return planted_instance(spec);
}

nlohmann::json solve_json(const std::string& arguments) {
  const auto result = run_cli("solve --json " + arguments);
  EXPECT_EQ(result.exit_code, 0) << result.out;
  return nlohmann::json::parse(result.out);
}

TEST(CliSolve, EverySolverOnBothFormsGivesTheSameOptimum) {
  const std::string json = write_temp_file("p1.json", write_instance_json(instance()));
  const std::string lp = write_temp_file("p1.lp", write_instance_lp(instance()));
  const nlohmann::json reference = solve_json("'" + json + "'");
  for (const char* key : {"solver", "status", "objective", "lower_bound", "gap", "seconds", "nodes",
                          "edges", "unmatchable_ports", "instance"})
    EXPECT_TRUE(reference.contains(key)) << key;
  EXPECT_EQ(reference["solver"], "exact");
  EXPECT_EQ(reference["status"], "optimal");
  EXPECT_EQ(reference["gap"], 0.0);
  EXPECT_EQ(reference["instance"]["ports"], 30);
  EXPECT_EQ(reference["instance"]["virtual_ports"], 2);
  for (const std::string solver : {"exact", "glpk", "glpk-tuned"}) {
    for (const std::string& file : {json, lp}) {
      const nlohmann::json r = solve_json("--solver " + solver + " '" + file + "'");
      EXPECT_EQ(r["status"], "optimal") << solver << " " << file;
      EXPECT_NEAR(r["objective"].get<double>(), reference["objective"].get<double>(), 1e-9)
          << solver << " " << file;
    }
  }
}

TEST(CliSolve, InfeasibleIsAnAnswer) {
  PlantedSpec spec;
  spec.ports = 7;  // odd, no virtual port
  const std::string path = write_temp_file("odd.json", write_instance_json(planted_instance(spec)));
  const nlohmann::json r = solve_json("'" + path + "'");
  EXPECT_EQ(r["status"], "infeasible");
  EXPECT_TRUE(r["objective"].is_null());
  EXPECT_TRUE(r["gap"].is_null());
  EXPECT_FALSE(r["unmatchable_ports"].empty());
  const auto text = run_cli("solve '" + path + "'");
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("exact: infeasible"), std::string::npos) << text.out;
}

TEST(CliSolve, BadInputAndUsageExitWithTwo) {
  const std::string broken = write_temp_file("broken.lp", {'M', 'i', 'n', '\n', 'x'});
  const auto parse = run_cli("solve '" + broken + "'", true);
  EXPECT_EQ(parse.exit_code, 2);
  EXPECT_NE(parse.out.find("broken.lp:2:"), std::string::npos) << parse.out;
  const std::string ok = write_temp_file("ok.json", write_instance_json(instance()));
  EXPECT_EQ(run_cli("solve '" + ok + "' --solver cplex").exit_code, 2);
  EXPECT_EQ(run_cli("solve '" + ok + "' --time-limit -1").exit_code, 2);
  EXPECT_EQ(run_cli("solve '" + ok + "' --max-edges 3").exit_code, 2);
  EXPECT_EQ(run_cli("solve").exit_code, 2);
  EXPECT_EQ(run_cli("solve /no/such/file.json").exit_code, 2);
  EXPECT_EQ(run_cli("solve --help").exit_code, 0);
}

// Below the optimum (and a little above it, for rounding), the instance left has fewer edges and
// the same optimum, for every solver.
TEST(CliReduce, WritesTheInstanceLeftBelowACostWithTheSameOptimum) {
  const std::string json = write_temp_file("full.json", write_instance_json(instance()));
  const double optimum = solve_json("'" + json + "'")["objective"].get<double>();
  char below[40];
  std::snprintf(below, sizeof below, "%.17g", optimum + 1e-7);
  for (const std::string name : {"left.lp", "left.json"}) {
    const std::string left = temp_path(name);
    const auto r = run_cli("reduce '" + json + "' --below " + below + " --output '" + left + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("checked lower bound"), std::string::npos) << r.out;
    EXPECT_LT(read_instance_file(left, Limits()).edges.size(), instance().edges.size()) << name;
    for (const std::string solver : {"exact", "glpk"}) {
      const nlohmann::json again = solve_json("--solver " + solver + " '" + left + "'");
      EXPECT_EQ(again["status"], "optimal") << name << " " << solver;
      EXPECT_NEAR(again["objective"].get<double>(), optimum, 1e-9) << name << " " << solver;
    }
  }
  // Below less than the optimum, what is left has no matching that cheap.
  std::snprintf(below, sizeof below, "%.17g", optimum - 1.0);
  const std::string none = temp_path("none.json");
  ASSERT_EQ(
      run_cli("reduce '" + json + "' --below " + below + " --output '" + none + "'").exit_code, 0);
  const nlohmann::json left = solve_json("'" + none + "'");
  if (left["status"] != "infeasible") EXPECT_GT(left["objective"].get<double>(), optimum - 1.0);
  for (const std::string bad : {"--below 3", "--below x --output a.lp", "--below 3 --output a.txt"})
    EXPECT_EQ(run_cli("reduce '" + json + "' " + bad, true).exit_code, 2) << bad;
}

TEST(CliLayout, ExportsTheP1InstanceItSolves) {
  const std::string mesh = write_temp_file("sphere.obj", write_obj(icosphere(3)));
  const std::string dir = temp_path("p1-export");
  const auto layout = run_cli("layout --json '" + mesh + "' --alpha 1 --export-p1 '" + dir + "'");
  ASSERT_EQ(layout.exit_code, 0) << layout.out;
  const nlohmann::json json = nlohmann::json::parse(layout.out);
  const std::string stem = dir + "/" + std::filesystem::path(mesh).stem().string() + "_a1";
  for (const char* extension : {".json", ".lp"}) {
    const nlohmann::json r = solve_json("'" + stem + extension + "'");
    EXPECT_EQ(r["status"], "optimal") << extension;
    EXPECT_EQ(r["instance"]["edges"], json["graph_edges"]) << extension;
    EXPECT_NEAR(r["objective"].get<double>(), json["objective"].get<double>(), 1e-9) << extension;
  }
}

// A thin torus whose first matching closes loops (layout_topology_test): every loop round's
// program is written after the first, and the last one's optimum is the layout's.
TEST(CliLayout, ExportsTheLoopRoundsItSolves) {
  const std::string mesh = write_temp_file("thin-torus.obj", write_obj(torus(1, 0.25, 64, 12)));
  const std::string dir = temp_path("p1-loop-rounds");
  const auto layout = run_cli("layout --json '" + mesh + "' --alpha 5 --export-p1 '" + dir + "'");
  ASSERT_EQ(layout.exit_code, 0) << layout.out;
  const nlohmann::json json = nlohmann::json::parse(layout.out);
  const int rounds = json["rounds"].get<int>();
  ASSERT_GE(rounds, 2);
  const std::string stem = dir + "/" + std::filesystem::path(mesh).stem().string() + "_a5";
  double objective = solve_json("'" + stem + ".json'")["objective"].get<double>();
  std::size_t conflicts = json["conflicts"].get<std::size_t>();
  for (int k = 2; k <= rounds; ++k) {
    const nlohmann::json r = solve_json("'" + stem + "_r" + std::to_string(k) + ".lp'");
    EXPECT_EQ(r["status"], "optimal") << k;
    EXPECT_GT(r["instance"]["conflicts"].get<std::size_t>(), conflicts) << k;
    EXPECT_GE(r["objective"].get<double>(), objective - 1e-9) << k;  // more conflicts
    conflicts = r["instance"]["conflicts"].get<std::size_t>();
    objective = r["objective"].get<double>();
  }
  EXPECT_EQ(conflicts,
            json["conflicts"].get<std::size_t>() + json["loop_conflicts"].get<std::size_t>());
  EXPECT_NEAR(objective, json["objective"].get<double>(), 1e-9);
  EXPECT_FALSE(std::filesystem::exists(stem + "_r" + std::to_string(rounds + 1) + ".lp"));
}

}  // namespace
}  // namespace tessera::matching
