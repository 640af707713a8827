// Quad layout bindings (thesis Ch. 4-6) on the session's parameterization: the graph of the ports
// is built once and kept, so that a new alpha only solves P1 again and redraws the layout (SPEC
// "Data flow"); the layout of the last alpha is kept for its GLB and PLY, written by the same core
// code as `tessera layout -o/--ply`. Progress goes to an optional JS onProgress(stage, fraction).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "export/glb.h"
#include "export/writers.h"
#include "guard.h"
#include "js_progress.h"
#include "layout/layout_json.h"
#include "layout/layout_scene.h"
#include "mesh_display.h"
#include "session.h"
#include "typed_arrays.h"

namespace tessera::wasm {
namespace {

using emscripten::val;

Session& session_with_param() {
  Session& s = session();
  if (!s.param)
    throw InputError(
        "there is no seamless parameterization of the mesh: compute the field and the "
        "parameterization first");
  return s;
}

Session& session_with_graph() {
  Session& s = session_with_param();
  if (!s.layout_graph)
    throw InputError("the graph of the ports has not been built: run the layout");
  return s;
}

layout::Charts charts_of(const Session& s) {
  return {*s.mesh, *s.connectivity, *s.param};
}

std::vector<float> to_floats(const std::vector<Eigen::Vector3d>& points) {
  std::vector<float> xyz;
  xyz.reserve(3 * points.size());
  for (const Eigen::Vector3d& p : points)
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(p[k]));
  return xyz;
}

// The figures of the graph alone (the layout's JSON repeats them with the solution's).
nlohmann::ordered_json graph_json(const layout::LayoutGraph& graph) {
  const layout::PortGraph& g = graph.graph;
  nlohmann::ordered_json json;
  json["singularities"] = g.ports.points.size();
  json["ports"] = g.port_count();
  json["virtual_ports"] = g.virtual_ports.size();
  json["graph_edges"] = g.edges.size();
  json["conflicts"] = g.conflicts.size();
  json["curved_edges"] = graph.curved_edges;
  json["length_doublings"] = graph.length_doublings;
  json["unmatchable_ports"] = graph.unmatchable_ports.size();
  json["average_separatrix_length"] = layout::average_separatrix_length(g);
  nlohmann::ordered_json seconds = nlohmann::ordered_json::object();
  for (const layout::StageSeconds& s : graph.seconds) seconds[s.stage] = s.seconds;
  json["seconds"] = seconds;
  return json;
}

// { positions: Float32Array (3 per singularity), valences: Int32Array }
val singularities_of(const Mesh& mesh, const layout::PortGraph& graph) {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::int32_t> valences;
  for (const layout::SingularPoint& point : graph.ports.points) {
    points.push_back(mesh.positions[point.ring.vertex]);
    valences.push_back(point.valence);
  }
  val result = val::object();
  result.set("positions", to_typed_array(to_floats(points)));
  result.set("valences", to_typed_array(valences));
  return result;
}

// { points: Float32Array (3 per point), offsets: Uint32Array (arcs + 1; arc i is the points
// offsets[i] .. offsets[i + 1] - 1) }
val arc_polylines(const layout::Charts& charts, const std::vector<layout::Arc>& arcs) {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> offsets{0};
  for (const layout::Arc& arc : arcs) {
    const std::vector<Eigen::Vector3d> line =
        layout::arc_polyline(charts.mesh, charts.connectivity, arc);
    points.insert(points.end(), line.begin(), line.end());
    offsets.push_back(static_cast<std::uint32_t>(points.size()));
  }
  val result = val::object();
  result.set("points", to_typed_array(to_floats(points)));
  result.set("offsets", to_typed_array(offsets));
  return result;
}

// Patches with other than four corners: the checker's most common verdict, as a number.
std::size_t patches_not_quads(const layout::LayoutCheck& check) {
  std::size_t count = 0;
  for (const auto& corners : check.corners) count += corners.size() != 4;
  return count;
}

// options: { solver: 'exact'|'glpk'|'glpk-tuned' } (default exact).
matching::SolverKind solver_of(const val& options) {
  const val solver_name =
      options.isUndefined() || options.isNull() ? val::undefined() : options["solver"];
  return matching::solver_kind_from_name(
      solver_name.isUndefined() ? "exact"
                                : (solver_name.isString() ? solver_name.as<std::string>() : ""));
}

// options: { rho } -> the graph's figures (graph_json). Drops the layout of the graph before.
val layout_graph(const val& options, const val& on_progress) {
  return guard([&] {
    Session& s = session_with_param();
    s.layout_graph.reset();
    s.resolve_cache = {};
    s.clear_quad_mesh();
    layout::LayoutOptions layout_options;
    layout_options.rho = number_option(options, "rho", layout_options.rho);
    if (!(layout_options.rho > 1)) throw InputError("option 'rho' must be a number above 1");
    s.layout_graph =
        layout::build_layout_graph(charts_of(s), layout_options, js_progress(on_progress));
    val result = val::object();
    result.set("info", json_to_val(graph_json(*s.layout_graph)));
    result.set("singularities", singularities_of(*s.mesh, s.layout_graph->graph));
    return result;
  });
}

// P1 at `alpha` on the kept graph, and the layout. options: solver_of()'s.
// -> { info: layout_json + problem_count, patches_not_quads; refined: { positions, triangles,
//      triangleFace, patch: Int32Array per triangle }, patchColors: Float32Array (3 per patch, the
//      GLB's colours), arcs: arc_polylines, singularities: singularities_of }
val layout_solve(double alpha, const val& options, const val& on_progress) {
  return guard([&] {
    Session& s = session_with_graph();
    if (!(alpha >= 0)) throw InputError("alpha must be a number >= 0");
    const layout::Charts charts = charts_of(s);
    s.clear_quad_mesh();
    layout::solve_layout(charts, *s.layout_graph, alpha, solver_of(options), Limits(),
                         js_progress(on_progress), &s.resolve_cache);
    const layout::QuadLayout& l = *s.resolve_cache.last;
    nlohmann::ordered_json info = layout::layout_json(*s.layout_graph, l);
    info["problem_count"] = l.check.problem_count;
    info["patches_not_quads"] = patches_not_quads(l.check);

    const std::vector<std::int32_t>& patch = l.refined.mesh.face_attributes.at("patch");
    val refined = val::object();
    set_display_arrays(refined, l.refined.mesh);
    refined.set("patch", to_typed_array(patch));
    std::int32_t patch_ids = 0;
    for (std::int32_t p : patch) patch_ids = std::max(patch_ids, p + 1);
    std::vector<float> colors;
    for (std::int32_t p = 0; p < patch_ids; ++p) {
      const Color c = layout::patch_color(p);
      colors.insert(colors.end(), {c.x(), c.y(), c.z()});
    }
    val result = val::object();
    result.set("info", json_to_val(info));
    result.set("refined", refined);
    result.set("patchColors", to_typed_array(colors));
    result.set("arcs", arc_polylines(charts, l.arcs));
    result.set("singularities", singularities_of(*s.mesh, s.layout_graph->graph));
    return result;
  });
}

// P1 at `alpha` on the kept graph into the session's ResolveCache (layout::presolve_layout()),
// for a layoutSolve() there later; the layout shown and exported stays. options: layoutSolve's and
// maxSeconds, the solves' time limit (at most the page's).
// -> whether the alpha is solved (false: no proven optimum within the limits).
val layout_presolve(double alpha, const val& options) {
  return guard([&] {
    Session& s = session_with_graph();
    if (!(alpha >= 0)) throw InputError("alpha must be a number >= 0");
    Limits limits;
    const double seconds = number_option(options, "maxSeconds", limits.max_solve_seconds);
    if (!(seconds > 0)) throw InputError("option 'maxSeconds' must be a number above 0");
    limits.max_solve_seconds = std::min(seconds, limits.max_solve_seconds);
    return val(layout::presolve_layout(charts_of(s), *s.layout_graph, alpha, solver_of(options),
                                       limits, Progress(), s.resolve_cache));
  });
}

const layout::QuadLayout& current_layout() {
  const Session& s = session();
  if (!s.resolve_cache.last || !s.layout_graph || !s.param)
    throw InputError("there is no quad layout to export: run the layout first");
  return *s.resolve_cache.last;
}

// The layout as GLB: the refined mesh coloured by patch with _PATCH, arcs, singularities, figures.
val layout_glb() {
  return guard([&] {
    const layout::QuadLayout& l = current_layout();
    const Session& s = session();
    return to_typed_array(write_glb(layout::layout_scene(charts_of(s), *s.layout_graph, l)));
  });
}

// The refined mesh as binary PLY with the integer face property "patch".
val layout_ply() {
  return guard([&] { return to_typed_array(write_ply(current_layout().refined.mesh)); });
}

}  // namespace

EMSCRIPTEN_BINDINGS(tessera_layout) {
  emscripten::function("layoutGraph", &layout_graph);
  emscripten::function("layoutSolve", &layout_solve);
  emscripten::function("layoutPresolve", &layout_presolve);
  emscripten::function("layoutGlb", &layout_glb);
  emscripten::function("layoutPly", &layout_ply);
}

}  // namespace tessera::wasm
