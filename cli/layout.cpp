// tessera layout <mesh>: the quad layout of a triangle mesh (thesis Ch. 3-6): cross field, seamless
// parameterization, separatrices and the graph of the ports, program P1, the layout and its check.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands.h"
#include "export/glb.h"
#include "export/write_mesh.h"
#include "export/writers.h"
#include "field_input.h"
#include "layout/layout_json.h"
#include "layout/layout_scene.h"
#include "layout/p1.h"
#include "layout_input.h"
#include "matching/instance_json.h"
#include "matching/instance_lp.h"
#include "mesh_input.h"
#include "param/seamless_param.h"

namespace tessera::cli {
namespace {

void print_layout_help() {
  std::printf(
      "usage: tessera layout <mesh> [--alpha 5] [--rho 10] [--h REL] [--field F] [-o layout.glb]\n"
      "                      [--ply layout.ply] [--export-p1 DIR] [--json] [field options] "
      "[options]\n\n"
      "Computes the quad layout of a triangle mesh as a minimum-weight perfect matching of the\n"
      "singularities' ports with conflict pairs (thesis Ch. 3-6): a cross field (or --field), its\n"
      "seamless parameterization, the separatrices grown from every port at unit speed, the edges\n"
      "of the port graph by the ratio test with singularity-free triangles, the illegal\n"
      "crossings, program P1 solved exactly, the mesh cut along the chosen arcs into patches,\n"
      "and the project's validity check (every patch a disk with four corners).\n\n"
      "  -o FILE.glb          the refined mesh coloured by patch with a per-face _PATCH\n"
      "                       attribute, the arcs as lines, the singularities as points\n"
      "  --ply FILE.ply       the refined mesh with an integer face property 'patch'\n"
      "  --export-p1 DIR      program P1 of this run as DIR/<mesh>_a<alpha>.lp (CPLEX LP, read by\n"
      "                       glpsol --lp and cbc) and DIR/<mesh>_a<alpha>.json (tessera solve),\n"
      "                       written before P1 is solved; the loop rounds' programs after it,\n"
      "                       as DIR/<mesh>_a<alpha>_r2.lp, _r3, ... (and .json)\n"
      "  --json               one JSON object on stdout: singularities, graph_edges, conflicts,\n"
      "                       patches, angle_rsd (percent), valid, objective, seconds (per\n"
      "                       stage), and alpha, ports, virtual_ports, nodes, arcs,\n"
      "                       solver, matching_status, matching_stopped_by (null,\n"
      "                       node_limit, time_guard), p1_nodes, lower_bound, curved_edges,\n"
      "                       twin_edges, loop_conflicts,\n"
      "                       trace_steps, trace_crossings,\n"
      "                       length_limit, length_doublings, unmatchable_ports,\n"
      "                       folded_singularities, stand_in_nodes (regular boundary\n"
      "                       vertices standing in as nodes where a part has none),\n"
      "                       average_separatrix_length, problems (the first 12),\n"
      "                       problem_count\n"
      "%s%s%s\n"
      "Exit codes: 0 ok (also for a layout the checker rejects: 'valid' says so), 1 internal\n"
      "error, 2 bad input (the message says what and where).\n",
      kLayoutInputHelp, kFieldInputHelp, kMeshInputHelp);
}

// Why P1 has no solution: its time ran out before a matching was found, or G has no perfect
// matching (the ports none covers, and the folded singular rings that leave singularities with
// fewer ports than their valence).
std::string no_matching_text(const nlohmann::ordered_json& json) {
  if (json["matching_status"] == "node_limit")
    return "  P1 found no matching within its node limit: raise --max-solve-nodes\n";
  if (json["matching_status"] == "time_limit")
    return "  P1 found no matching before its time guard: raise --max-solve-seconds\n";
  const auto list = [](const nlohmann::ordered_json& items) {
    std::string text;
    for (std::size_t k = 0; k < items.size() && k < 12; ++k)
      text += (k ? ", " : "") + items[k].dump();
    return items.size() > 12 ? text + ", ..." : text;
  };
  const auto& unmatchable = json["unmatchable_ports"];
  if (unmatchable.empty()) return {};
  std::string result = "  G has no perfect matching: no matching covers ports " +
                       list(unmatchable) + " (L_max doubled " + json["length_doublings"].dump() +
                       " times)\n";
  const auto& folded = json["folded_singularities"];
  if (!folded.empty())
    result += "  the parameterization folds the rings of " + std::to_string(folded.size()) +
              " singularities (vertices " + list(folded) +
              "): flipped triangles leave them fewer ports than their valence; a smoother field "
              "avoids this\n";
  return result;
}

std::string layout_text(const nlohmann::ordered_json& json) {
  char text[512];
  std::snprintf(
      text, sizeof text,
      "%d singularities, %d ports (%d virtual), %d graph edges, %d conflicts\n"
      "P1 %s, objective %s; %d patches, %d nodes, %d arcs, angle RSD %.2f %%\nlayout %s\n",
      json["singularities"].get<int>(), json["ports"].get<int>(), json["virtual_ports"].get<int>(),
      json["graph_edges"].get<int>(), json["conflicts"].get<int>(),
      json["matching_status"].get<std::string>().c_str(), json["objective"].dump().c_str(),
      json["patches"].get<int>(), json["nodes"].get<int>(), json["arcs"].get<int>(),
      json["angle_rsd"].get<double>(), json["valid"].get<bool>() ? "valid" : "INVALID");
  std::string result = text;
  if (json["matching_stopped_by"] == "node_limit")
    result += "  P1 stopped at its node limit (" + json["p1_nodes"].dump() +
              " nodes; --max-solve-nodes): the best matching found, the same on every run\n";
  if (json["matching_stopped_by"] == "time_guard")
    result +=
        "  P1 stopped at its time guard (--max-solve-seconds): this result depends on the "
        "machine's speed and load, another run may differ\n";
  result += no_matching_text(json);
  for (const auto& problem : json["problems"]) result += "  " + problem.get<std::string>() + "\n";
  if (json["problem_count"].get<std::size_t>() > json["problems"].size())
    result +=
        "  ... " + std::to_string(json["problem_count"].get<std::size_t>()) + " problems in all\n";
  for (const auto& [stage, seconds] : json["seconds"].items()) {
    std::snprintf(text, sizeof text, "  %-14s %.3f s\n", stage.c_str(), seconds.get<double>());
    result += text;
  }
  return result;
}

// One program P1 of the run (Ch. 5) as DIR/<mesh>_a<alpha><round>.{lp,json}, the instance files
// of issue 5, so that the bench solves exactly what the layout solves.
void export_p1(const std::string& dir, const std::string& mesh_path, double alpha,
               const std::string& round, const matching::MatchingProblem& problem) {
  std::filesystem::create_directories(dir);
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, "_a%g", alpha);
  const std::filesystem::path stem =
      std::filesystem::path(dir) /
      (std::filesystem::path(mesh_path).stem().string() + suffix + round);
  write_file_bytes(stem.string() + ".json", matching::write_instance_json(problem));
  write_file_bytes(stem.string() + ".lp", matching::write_instance_lp(problem));
}

// The loop rounds' programs (the first round's `problem` with the loop conflicts of the rounds
// before) as DIR/<mesh>_a<alpha>_r<k>, k = 2, 3, ...: the slider's re-solves spend most of their
// P1 time in them.
void export_loop_rounds(const std::string& dir, const std::string& mesh_path,
                        matching::MatchingProblem problem, const layout::QuadLayout& layout) {
  for (std::size_t k = 0; k < layout.loop_rounds.size(); ++k) {
    layout::add_loop_conflicts(layout.loop_rounds[k], problem);
    export_p1(dir, mesh_path, layout.alpha, "_r" + std::to_string(k + 2), problem);
  }
}

}  // namespace

int layout_command(const Args& args) {
  std::set<std::string> values = mesh_input_options();
  values.merge(field_input_options());
  values.merge(layout_input_options());
  values.insert({"-o", "--ply", "--export-p1"});
  const ParsedArgs parsed = parse_args(args, values, {"--json", "--help", "-h"}, "layout");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_layout_help();
    return 0;
  }
  if (parsed.positional.size() != 1)
    throw UsageError("'tessera layout' takes one mesh file; run 'tessera layout --help'");
  const double alpha = layout_alpha(parsed);
  const ParamOptions param_options = layout_param_options(parsed);
  const layout::LayoutOptions options = layout_options(parsed);
  const matching::SolverKind solver = layout_solver(parsed);

  const Mesh mesh = load_triangle_mesh_argument(parsed.positional[0], parsed);
  const Progress progress = stderr_progress();
  const auto start = std::chrono::steady_clock::now();
  const Connectivity connectivity = build_connectivity(mesh);
  const FaceFrames frames = face_frames(mesh);
  const CrossField field = field_from_arguments(mesh, connectivity, frames, parsed, progress);
  const SeamlessParam param =
      seamless_parameterization(mesh, connectivity, frames, field, param_options, progress);
  const double param_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const layout::Charts charts{mesh, connectivity, param};
  layout::LayoutGraph graph = layout::build_layout_graph(charts, options, progress);
  graph.seconds.insert(graph.seconds.begin(), {"field and param", param_seconds});
  const std::optional<matching::MatchingProblem> first_round =
      parsed.has("--export-p1") ? std::optional(layout::matching_problem(graph.graph, alpha))
                                : std::nullopt;
  if (first_round)
    export_p1(parsed.value("--export-p1"), parsed.positional[0], alpha, "", *first_round);
  const layout::QuadLayout result =
      layout::solve_layout(charts, graph, alpha, solver, options.limits, progress);
  if (first_round)
    export_loop_rounds(parsed.value("--export-p1"), parsed.positional[0], *first_round, result);

  if (parsed.has("-o"))
    write_file_bytes(parsed.value("-o"), write_glb(layout::layout_scene(charts, graph, result)));
  if (parsed.has("--ply")) write_file_bytes(parsed.value("--ply"), write_ply(result.refined.mesh));
  const nlohmann::ordered_json json = layout::layout_json(graph, result);
  std::printf("%s",
              parsed.has("--json") ? (json.dump(2) + "\n").c_str() : layout_text(json).c_str());
  return 0;
}

}  // namespace tessera::cli
