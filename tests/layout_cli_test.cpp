// tessera layout on a generated mesh: the JSON keys of issue 4 with a valid layout, the PLY with an
// integer face property 'patch', the GLB with the _PATCH attribute, arcs and singularities, exit
// codes for bad options.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "export/writers.h"
#include "mesh/load.h"
#include "mesh/readers.h"
#include "mesh/shapes.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::quoted;
using test::run_cli;
using test::temp_path;
using test::write_temp_file;

TEST(CliLayout, WritesJsonPlyAndGlb) {
  const std::string path = write_temp_file("sphere.obj", write_obj(icosphere(3)));
  const std::string ply = temp_path("layout.ply"), glb = temp_path("layout.glb");
  const auto result = run_cli("layout --json " + quoted(path) + " --alpha 5 --ply " + quoted(ply) +
                              " -o " + quoted(glb));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const auto json = nlohmann::json::parse(result.out);
  for (const char* key : {"singularities", "graph_edges", "conflicts", "patches", "angle_rsd",
                          "valid", "objective", "seconds"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["singularities"], 8);
  EXPECT_TRUE(json["valid"].get<bool>());
  EXPECT_EQ(json["problem_count"], 0);
  EXPECT_GT(json["graph_edges"].get<int>(), json["ports"].get<int>());
  for (const char* stage : {"separatrices", "conflicts", "P1", "layout", "check"})
    EXPECT_TRUE(json["seconds"].contains(stage)) << stage;
  // L_max scales with --length-factor (before any doubling, Sec. 5.1).
  const auto shorter = run_cli("layout --json " + quoted(path) + " --length-factor 1.5");
  ASSERT_EQ(shorter.exit_code, 0) << shorter.out;
  const auto short_json = nlohmann::json::parse(shorter.out);
  EXPECT_NEAR(short_json["length_limit"].get<double>() *
                  std::pow(2.0, json["length_doublings"].get<int>() -
                                    short_json["length_doublings"].get<int>()),
              json["length_limit"].get<double>() / 2, 1e-9 * json["length_limit"].get<double>());

  const LoadedMesh refined = load_mesh_file(ply);
  const auto& patch = refined.mesh.face_attributes.at("patch");
  EXPECT_EQ(*std::max_element(patch.begin(), patch.end()) + 1, json["patches"].get<int>());
  EXPECT_EQ(*std::min_element(patch.begin(), patch.end()), 0);

  const std::vector<std::uint8_t> bytes = read_file_bytes(glb, Limits{});
  const std::string text(bytes.begin(), bytes.end());
  EXPECT_EQ(text.substr(0, 4), "glTF");
  for (const char* name : {"_PATCH", "arcs", "singularities valence 3", "angle_rsd"})
    EXPECT_NE(text.find(name), std::string::npos) << name;
}

TEST(CliLayout, BadOptionsExitWithTwo) {
  const std::string path = write_temp_file("sphere.obj", write_obj(icosphere(1)));
  EXPECT_EQ(run_cli("layout " + quoted(path) + " --alpha -1").exit_code, 2);
  EXPECT_EQ(run_cli("layout " + quoted(path) + " --rho 0.5").exit_code, 2);
  EXPECT_EQ(run_cli("layout " + quoted(path) + " --max-solve-seconds 0").exit_code, 2);
  EXPECT_EQ(run_cli("layout " + quoted(path) + " --length-factor 0").exit_code, 2);
  EXPECT_EQ(run_cli("layout " + quoted(path) + " --length-factor nan").exit_code, 2);
  EXPECT_EQ(run_cli("layout").exit_code, 2);
  EXPECT_EQ(run_cli("layout --help").exit_code, 0);
  const auto limited = run_cli("layout " + quoted(path) + " --max-trace-steps 10", true);
  EXPECT_EQ(limited.exit_code, 2);
  EXPECT_NE(limited.out.find("--max-trace-steps"), std::string::npos) << limited.out;
  const auto crossings = run_cli("layout " + quoted(path) + " --max-trace-crossings 3", true);
  EXPECT_EQ(crossings.exit_code, 2);
  EXPECT_NE(crossings.out.find("separatrix tracing (crossings found) has 4, above the limit of 3; "
                               "raise it with --max-trace-crossings"),
            std::string::npos)
      << crossings.out;
  const auto guard = run_cli("layout " + quoted(path) + " --max-trace-seconds 1e-9", true);
  EXPECT_EQ(guard.exit_code, 2);
  EXPECT_NE(guard.out.find("passed its time guard"), std::string::npos) << guard.out;
  EXPECT_NE(guard.out.find("raise it with --max-trace-seconds"), std::string::npos) << guard.out;
}

// `tessera layout --json` without the seconds, which alone may differ from run to run.
nlohmann::json layout_without_seconds(const std::string& arguments) {
  const auto result = run_cli("layout --json " + arguments);
  EXPECT_EQ(result.exit_code, 0) << result.out;
  nlohmann::json json = nlohmann::json::parse(result.out);
  json.erase("seconds");
  return json;
}

// P1 stopped by its node limit: the best matching found, the same on every run, and said so.
TEST(CliLayout, ANodeLimitStopsP1TheSameWayOnEveryRun) {
  const std::string path = write_temp_file("part.obj", write_obj(mechanical_part(3)));
  const std::string arguments = quoted(path) + " --alpha 0 --max-solve-nodes 1";
  const nlohmann::json first = layout_without_seconds(arguments);
  EXPECT_EQ(first["matching_status"], "feasible");
  EXPECT_EQ(first["matching_stopped_by"], "node_limit");
  EXPECT_EQ(first, layout_without_seconds(arguments));
  const auto text = run_cli("layout " + arguments);
  EXPECT_NE(text.out.find("P1 stopped at its node limit"), std::string::npos) << text.out;
  // Without the limit: proven optimal, stopped by nothing, and again the same on every run.
  const nlohmann::json full = layout_without_seconds(quoted(path) + " --alpha 0");
  EXPECT_EQ(full["matching_status"], "optimal");
  EXPECT_TRUE(full["matching_stopped_by"].is_null());
  EXPECT_GT(full["p1_nodes"].get<int>(), 1);
  EXPECT_LT(full["objective"].get<double>(), first["objective"].get<double>() + 1e-9);
  EXPECT_EQ(full, layout_without_seconds(quoted(path) + " --alpha 0"));
}

// A P1 stopped by its time guard before any matching: the text says so, that the result depends on
// the machine, and names the option to raise.
TEST(CliLayout, NoMatchingWithinTheSolveTimeIsExplained) {
  const std::string path = write_temp_file("part.obj", write_obj(mechanical_part(3)));
  const std::string arguments = quoted(path) + " --alpha 0 --max-solve-seconds 1e-9";
  const auto result = run_cli("layout " + arguments);
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("P1 time_limit, objective null"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("P1 stopped at its time guard"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("depends on the machine's speed and load"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("raise --max-solve-seconds"), std::string::npos) << result.out;
  EXPECT_EQ(layout_without_seconds(arguments)["matching_stopped_by"], "time_guard");
}

}  // namespace
}  // namespace tessera
