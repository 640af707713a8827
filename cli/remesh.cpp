// tessera remesh <mesh>: a quad mesh out of the quad layout of a triangle mesh (thesis Ch. 8): the
// layout as `tessera layout` computes it, integer side lengths for a target size, the patches
// mapped onto their rectangles, one conforming all-quad mesh with its quality figures.
#include <chrono>
#include <cstdio>

#include "commands.h"
#include "export/write_mesh.h"
#include "export/writers.h"
#include "field_input.h"
#include "layout_input.h"
#include "mesh_input.h"
#include "remesh/hausdorff.h"
#include "remesh/remesh.h"
#include "remesh/remesh_json.h"

namespace tessera::cli {
namespace {

void print_remesh_help() {
  std::printf(
      "usage: tessera remesh <mesh> [--quads N | --edge-length L | --lambda S] -o out.obj|.ply\n"
      "                      [--json] [layout options] [field options] [options]\n\n"
      "Computes the quad layout of the mesh (as 'tessera layout'), gives every chain of opposite\n"
      "patch sides one positive integer (thesis Sec. 8.1), maps each patch onto its n x m\n"
      "rectangle by Wachspress coordinates (Sec. 8.2) and writes one conforming all-quad mesh\n"
      "whose base complex is the layout, with the face attribute 'patch' (PLY: an integer face\n"
      "property; GLB: _PATCH).\n\n"
      "  --quads N            about N quads (the scale lambda bisected for the closest count)\n"
      "  --edge-length L      quad edges of about L (in the mesh's units) on average\n"
      "  --lambda S           parameter units per quad edge (default 1, as in Sec. 8.3; the\n"
      "                       parameter unit is --h times the bounding-box diagonal)\n"
      "  --smooth             then relax the whole mesh on the input surface (beyond the thesis:\n"
      "                       the patch maps are only C0 across sides): every vertex but the\n"
      "                       layout's nodes and the boundary moves halfway to the mean of its\n"
      "                       neighbours and back onto the surface, --smooth-rounds times\n"
      "  --smooth-rounds N    rounds of --smooth (default 10)\n"
      "  -o FILE              the quad mesh: .obj, .ply, .off, .glb (required)\n"
      "  --json               one JSON object on stdout: quads, vertices, irregular_vertices,\n"
      "                       patches, layout_valid, lambda, chains, compressed_sides (sides\n"
      "                       whose chain gives them quads 4 times shorter than the rest, Fig.\n"
      "                       8.1), min_scaled_jacobian,\n"
      "                       mean_scaled_jacobian, nonpositive_jacobian_quads,\n"
      "                       nonpositive_corners (and _at_nodes: at a layout node), "
      "flipped_quads,\n"
      "                       max_angle_deviation, mean_angle_deviation (degrees), manifold,\n"
      "                       boundary_edges, euler_characteristic, input_euler_characteristic,\n"
      "                       irregular_off_nodes, hausdorff_relative (the distance between\n"
      "                       the quad mesh and the input, sampled at both meshes' vertices and\n"
      "                       face centroids, over the bounding-box diagonal), seconds (per step)\n"
      "%s%s%s\n"
      "Exit codes: 0 ok, 1 internal error, 2 bad input (also a layout the checker rejects: the\n"
      "message names its first problem; try another --alpha).\n",
      kLayoutInputHelp, kFieldInputHelp, kMeshInputHelp);
}

remesh::SizeTarget size_target(const ParsedArgs& parsed) {
  const int given = parsed.has("--quads") + parsed.has("--edge-length") + parsed.has("--lambda");
  if (given > 1) throw UsageError("give one of --quads, --edge-length and --lambda");
  remesh::SizeTarget target;
  if (parsed.has("--quads")) {
    target.quads = parsed.count("--quads", 0);
    if (target.quads == 0 || target.quads > 100000000)
      throw UsageError("--quads expects a count in [1, 100000000]");
  }
  target.edge_length = parsed.number("--edge-length", 0);
  if (parsed.has("--edge-length") && !(target.edge_length > 0))
    throw UsageError("--edge-length expects a positive number");
  target.lambda = parsed.number("--lambda", target.lambda);
  if (!(target.lambda > 0)) throw UsageError("--lambda expects a positive number");
  return target;
}

long euler_characteristic(const Mesh& mesh, const Connectivity& connectivity) {
  return long(mesh.vertex_count()) - long(connectivity.edge_count()) + long(mesh.face_count());
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string remesh_text(const nlohmann::ordered_json& json) {
  char text[768];
  std::snprintf(
      text, sizeof text,
      "%d quads, %d vertices (%d irregular), %d patches, lambda %.4g\n"
      "scaled Jacobian min %.3f mean %.3f (%d quads <= 0), %d flipped; angle deviation max "
      "%.1f mean %.1f degrees\n%s, %d boundary edges, Euler characteristic %d (input %d)\n",
      json["quads"].get<int>(), json["vertices"].get<int>(), json["irregular_vertices"].get<int>(),
      json["patches"].get<int>(), json["lambda"].get<double>(),
      json["min_scaled_jacobian"].get<double>(), json["mean_scaled_jacobian"].get<double>(),
      json["nonpositive_jacobian_quads"].get<int>(), json["flipped_quads"].get<int>(),
      json["max_angle_deviation"].get<double>(), json["mean_angle_deviation"].get<double>(),
      json["manifold"].get<bool>() ? "manifold" : "NOT MANIFOLD", json["boundary_edges"].get<int>(),
      json["euler_characteristic"].get<int>(), json["input_euler_characteristic"].get<int>());
  std::string result = text;
  for (const auto& [stage, seconds] : json["seconds"].items()) {
    std::snprintf(text, sizeof text, "  %-16s %.3f s\n", stage.c_str(), seconds.get<double>());
    result += text;
  }
  return result;
}

}  // namespace

int remesh_command(const Args& args) {
  std::set<std::string> values = mesh_input_options();
  values.merge(field_input_options());
  values.merge(layout_input_options());
  values.insert({"--quads", "--edge-length", "--lambda", "--smooth-rounds", "-o"});
  const ParsedArgs parsed =
      parse_args(args, values, {"--json", "--smooth", "--help", "-h"}, "remesh");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_remesh_help();
    return 0;
  }
  if (parsed.positional.size() != 1)
    throw UsageError("'tessera remesh' takes one mesh file; run 'tessera remesh --help'");
  if (!parsed.has("-o")) throw UsageError("'tessera remesh' needs an output file: -o out.obj");
  check_mesh_format(parsed.value("-o"));
  const remesh::SizeTarget target = size_target(parsed);
  const std::size_t rounds = parsed.count("--smooth-rounds", 10);
  if (rounds > 1000) throw UsageError("--smooth-rounds expects a count up to 1000");
  const int smoothing_rounds = parsed.has("--smooth") ? static_cast<int>(rounds) : 0;
  const double alpha = layout_alpha(parsed);
  const ParamOptions param_options = layout_param_options(parsed);
  const layout::LayoutOptions options = layout_options(parsed);
  const matching::SolverKind solver = layout_solver(parsed);

  const Mesh mesh = load_triangle_mesh_argument(parsed.positional[0], parsed);
  const Progress progress = stderr_progress();
  nlohmann::ordered_json seconds;
  auto start = std::chrono::steady_clock::now();
  const Connectivity connectivity = build_connectivity(mesh);
  const FaceFrames frames = face_frames(mesh);
  const CrossField field = field_from_arguments(mesh, connectivity, frames, parsed, progress);
  const SeamlessParam param =
      seamless_parameterization(mesh, connectivity, frames, field, param_options, progress);
  seconds["field and param"] = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const layout::Charts charts{mesh, connectivity, param};
  const layout::LayoutGraph graph = layout::build_layout_graph(charts, options, progress);
  const layout::QuadLayout layout =
      layout::solve_layout(charts, graph, alpha, solver, options.limits, progress);
  seconds["layout"] = seconds_since(start);
  const remesh::QuadMesh quads = remesh::remesh_layout(layout, target, smoothing_rounds, &mesh);
  for (const layout::StageSeconds& s : quads.seconds) seconds[s.stage] = s.seconds;
  start = std::chrono::steady_clock::now();
  const double hausdorff = remesh::relative_hausdorff(mesh, quads.mesh);
  seconds["hausdorff"] = seconds_since(start);
  start = std::chrono::steady_clock::now();
  write_mesh_file(parsed.value("-o"), quads.mesh);
  seconds["write"] = seconds_since(start);

  const nlohmann::ordered_json json =
      remesh::remesh_json(quads, euler_characteristic(mesh, connectivity), hausdorff, seconds);
  std::printf("%s",
              parsed.has("--json") ? (json.dump(2) + "\n").c_str() : remesh_text(json).c_str());
  return 0;
}

}  // namespace tessera::cli
