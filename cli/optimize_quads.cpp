// tessera optimize-quads <quadmesh>: quad-mesh structure optimization (thesis Ch. 7): the trivial
// base complex of a quad mesh, the supergraph along it, program P1, and the optimized layout over
// the quad mesh.
#include <cstdio>

#include "commands.h"
#include "export/write_mesh.h"
#include "layout_input.h"
#include "mesh_input.h"
#include "quadmesh/quad_input.h"
#include "quadmesh/quadmesh_json.h"
#include "remesh/remesh.h"
#include "stderr_progress.h"

namespace tessera::cli {
namespace {

void print_optimize_quads_help() {
  std::printf(
      "usage: tessera optimize-quads <quadmesh> [--alpha 5] [--no-diagonals] [--split]\n"
      "                              [-o out.ply] [--json] [options]\n\n"
      "Optimizes the base complex of a quad mesh (thesis Ch. 7): traces every edge line from\n"
      "every irregular vertex until it reaches another one or the boundary (the trivial base\n"
      "complex B), builds the graph of the ports along B in the integer metric (ratio test and\n"
      "window reduction at every regular vertex where two separatrices cross, multi-edges and\n"
      "diagonal edges kept, illegal crossings and zero-area pairs as conflicts), solves program\n"
      "P1 exactly and writes the coarser layout over the quad mesh. The irregular vertices stay\n"
      "where they are.\n\n"
      "  --alpha A            edge weight L_base + A * L_height (default 5)\n"
      "  --no-diagonals       no diagonal edges (L_base = L_height, Sec. 7.5): straighter\n"
      "                       corners at singularities, usually more patches\n"
      "  --split              split every face into quads first (a triangle or n-gon into 3 or n\n"
      "                       quads, all other faces into 4 to keep the mesh conforming); without\n"
      "                       it a mesh with faces that are not quads is refused\n"
      "  --join-triangles     a quad mesh saved as triangles (GLB, STL: each quad's two triangles\n"
      "                       one after the other) joined back into its quads\n"
      "  --solver S           P1 solver: exact (default), glpk or glpk-tuned\n"
      "  --max-solve-nodes N  branch-and-bound nodes of P1 with its rounds (default 5000)\n"
      "  --max-solve-seconds S  time guard of P1 (default 1800)\n"
      "  -o FILE              the layout over the quad mesh (.ply, .obj, .off, .glb): every quad\n"
      "                       that no arc cuts is kept, the quads an arc crosses diagonally are\n"
      "                       split along it into triangles; integer face properties 'patch' and\n"
      "                       'quad' (the input quad of each face) in PLY\n"
      "  --remesh FILE        also a new all-quad mesh whose base complex is the optimized\n"
      "                       layout (thesis Ch. 8 at one quad per parameter unit: about the\n"
      "                       input's resolution), with the face attribute 'patch'; its arcs\n"
      "                       run along its edges, and its irregular vertices are the input's\n"
      "  --json               one JSON object on stdout: singularities, base_complex_patches,\n"
      "                       patches, angle_rsd, graph_edges, conflicts, matching_status,\n"
      "                       seconds, and quads, valid, base_complex_valid, objective,\n"
      "                       lower_bound, matching_stopped_by, alpha, diagonals, ports,\n"
      "                       virtual_ports, separatrix_edges, crossing_edges, diagonal_edges,\n"
      "                       zero_area_pairs, rejected_by_window, curved_edges, twin_edges,\n"
      "                       cut_quads, rounds, p1_nodes, problems, problem_count; with\n"
      "                       --remesh also remeshed_quads, remeshed_irregular_vertices\n"
      "%s\n"
      "Exit codes: 0 ok (also for a layout the checker rejects: 'valid' says so), 1 internal\n"
      "error, 2 bad input (the message says what and where).\n",
      kMeshInputHelp);
}

std::string optimize_quads_text(const nlohmann::ordered_json& json) {
  char text[512];
  std::snprintf(
      text, sizeof text,
      "%d quads, %d irregular vertices, %d ports (%d virtual)\n"
      "base complex: %d patches (%s)\n"
      "supergraph: %d edges, %d conflicts; P1 %s, objective %s\n"
      "optimized: %d patches, angle RSD %.2f %%, %d quads cut by arcs; layout %s\n",
      json["quads"].get<int>(), json["singularities"].get<int>(), json["ports"].get<int>(),
      json["virtual_ports"].get<int>(), json["base_complex_patches"].get<int>(),
      json["base_complex_valid"].get<bool>() ? "valid" : "INVALID", json["graph_edges"].get<int>(),
      json["conflicts"].get<int>(), json["matching_status"].get<std::string>().c_str(),
      json["objective"].dump().c_str(), json["patches"].get<int>(), json["angle_rsd"].get<double>(),
      json["cut_quads"].get<int>(), json["valid"].get<bool>() ? "valid" : "INVALID");
  std::string result = text;
  for (const auto& problem : json["problems"]) result += "  " + problem.get<std::string>() + "\n";
  for (const auto& [stage, seconds] : json["seconds"].items()) {
    std::snprintf(text, sizeof text, "  %-14s %.3f s\n", stage.c_str(), seconds.get<double>());
    result += text;
  }
  return result;
}

}  // namespace

int optimize_quads_command(const Args& args) {
  std::set<std::string> values = mesh_input_options();
  values.insert(
      {"--alpha", "--solver", "--max-solve-nodes", "--max-solve-seconds", "-o", "--remesh"});
  const ParsedArgs parsed = parse_args(
      args, values, {"--json", "--no-diagonals", "--split", "--join-triangles", "--help", "-h"},
      "optimize-quads");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_optimize_quads_help();
    return 0;
  }
  if (parsed.positional.size() != 1)
    throw UsageError(
        "'tessera optimize-quads' takes one quad mesh file; run 'tessera optimize-quads --help'");
  if (parsed.has("-o")) check_mesh_format(parsed.value("-o"));
  if (parsed.has("--remesh")) check_mesh_format(parsed.value("--remesh"));
  const double alpha = layout_alpha(parsed);
  const matching::SolverKind solver = layout_solver(parsed);
  const Limits limits = layout_options(parsed).limits;
  quadmesh::SupergraphOptions options;
  options.diagonals = !parsed.has("--no-diagonals");

  const std::string& path = parsed.positional[0];
  LoadedMesh loaded = load_mesh_argument(path, parsed);
  for (const std::string& warning : loaded.report.warnings)
    std::fprintf(stderr, "tessera: warning: %s\n", warning.c_str());
  if (parsed.has("--split") && parsed.has("--join-triangles"))
    throw UsageError("give one of --split and --join-triangles");
  if (parsed.has("--split")) {
    loaded.mesh = quadmesh::split_into_quads(loaded.mesh);
  } else if (parsed.has("--join-triangles")) {
    loaded.mesh = quadmesh::join_triangle_pairs(loaded.mesh, path);
    validate_mesh(loaded.mesh);
    quadmesh::require_quad_mesh(loaded.mesh, path);
  } else {
    quadmesh::require_quad_mesh(loaded.mesh, path);
  }
  const Progress progress = stderr_progress();
  const quadmesh::QuadGraph graph =
      quadmesh::build_quad_graph(std::move(loaded.mesh), options, progress);
  const quadmesh::QuadLayoutResult result =
      quadmesh::optimize_quad_layout(graph, alpha, solver, limits, progress);
  if (parsed.has("-o")) write_mesh_file(parsed.value("-o"), result.mesh);
  nlohmann::ordered_json json = quadmesh::quad_layout_json(graph, result, options.diagonals);
  if (parsed.has("--remesh")) {
    if (!result.check.valid())
      throw InputError("the optimized layout is not valid (" + json["problems"][0].dump() +
                       "): there is no quad mesh to write; try another --alpha");
    // Ch. 8 with one parameter unit per quad edge: the input's resolution.
    const remesh::QuadMesh remeshed = remesh::remesh_layout(result.layout, remesh::SizeTarget());
    write_mesh_file(parsed.value("--remesh"), remeshed.mesh);
    for (const layout::StageSeconds& stage : remeshed.seconds)
      json["seconds"]["remesh " + stage.stage] = stage.seconds;
    json["remeshed_quads"] = remeshed.mesh.face_count();
    json["remeshed_irregular_vertices"] = remeshed.quality.irregular_vertices;
  }
  std::printf("%s", parsed.has("--json") ? (json.dump(2) + "\n").c_str()
                                         : optimize_quads_text(json).c_str());
  return 0;
}

}  // namespace tessera::cli
