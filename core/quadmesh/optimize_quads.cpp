#include "quadmesh/optimize_quads.h"

#include <chrono>

#include "base/error.h"
#include "layout/arcs.h"
#include "layout/conflicts.h"
#include "layout/twin_edges.h"
#include "quadmesh/repair.h"

namespace tessera::quadmesh {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point& start) {
  const Clock::time_point now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
}

}  // namespace

QuadGraph build_quad_graph(Mesh quads, const SupergraphOptions& options, const Progress& progress) {
  QuadGraph g;
  auto start = Clock::now();
  std::vector<layout::StageSeconds>& seconds = g.layout_graph.seconds;
  g.quads = std::move(quads);
  g.connectivity = build_connectivity(g.quads);
  g.charts = integer_charts(g.quads, g.connectivity);
  if (g.charts.param.singularities.empty())
    throw InputError(
        "the quad mesh has no irregular vertex (every interior vertex has four quads, every "
        "boundary vertex two): its trivial base complex has no separatrix, there is no layout "
        "to optimize");
  seconds.push_back({"charts", seconds_since(start)});
  progress.step("base complex", 0);
  g.base = trivial_base_complex(g.quads, g.connectivity);
  seconds.push_back({"base complex", seconds_since(start)});
  progress.step("supergraph", 0);
  g.supergraph = build_supergraph(g.quads, g.connectivity, g.charts, g.base, options);
  layout::LayoutGraph& lg = g.layout_graph;
  lg.graph = std::move(g.supergraph.graph);
  const std::size_t candidates = lg.graph.edges.size();
  const layout::Charts charts = g.charts.charts();
  lg.arcs = layout::keep_edges_with_arcs(charts, lg.graph);
  lg.curved_edges = candidates - lg.graph.edges.size();
  lg.twin_edges = layout::merge_twin_edges(lg.graph, lg.arcs);
  seconds.push_back({"supergraph", seconds_since(start)});
  lg.graph.conflicts = layout::illegal_crossings(charts, lg.graph, lg.arcs, progress);
  lg.repair_pairs = quad_repair_pairs;
  seconds.push_back({"conflicts", seconds_since(start)});
  return g;
}

Mesh layout_over_quads(const Mesh& quads, const layout::RefinedMesh& refined,
                       const std::vector<std::int32_t>& patch, std::size_t& cut_quads) {
  const std::size_t quad_count = quads.face_count();
  std::vector<std::vector<Index>> pieces(quad_count);  // refined faces per quad
  for (Index f = 0; f < refined.mesh.face_count(); ++f) pieces[refined.parent[f] / 2].push_back(f);
  Mesh result;
  result.positions = refined.mesh.positions;
  std::vector<std::int32_t>& patch_of = result.face_attributes["patch"];
  std::vector<std::int32_t>& quad_of = result.face_attributes["quad"];
  cut_quads = 0;
  for (std::size_t q = 0; q < quad_count; ++q) {
    const std::vector<Index>& here = pieces[q];
    // One face per triangle is the triangle itself: a point on its edge from a cut neighbour
    // would have split it too (the refined mesh is conforming).
    const bool whole = here.size() == 2 && refined.parent[here[0]] != refined.parent[here[1]] &&
                       patch[here[0]] == patch[here[1]];
    if (whole) {
      result.add_face(quads.face(q));
      patch_of.push_back(patch[here[0]]);
      quad_of.push_back(static_cast<std::int32_t>(q));
      continue;
    }
    ++cut_quads;
    for (Index f : here) {
      result.add_face(refined.mesh.face(f));
      patch_of.push_back(patch[f]);
      quad_of.push_back(static_cast<std::int32_t>(q));
    }
  }
  return result;
}

QuadLayoutResult optimize_quad_layout(const QuadGraph& graph, double alpha,
                                      matching::SolverKind solver, const Limits& limits,
                                      const Progress& progress) {
  QuadLayoutResult result;
  result.layout = layout::solve_layout(graph.charts.charts(), graph.layout_graph, alpha, solver,
                                       limits, progress);
  result.seconds = result.layout.seconds;
  const auto& attributes = result.layout.refined.mesh.face_attributes;
  const auto patch = attributes.find("patch");
  if (patch == attributes.end()) return result;  // P1 found no matching: no layout
  auto start = Clock::now();
  result.mesh =
      layout_over_quads(graph.quads, result.layout.refined, patch->second, result.cut_quads);
  result.check = layout::check_layout(result.mesh, result.mesh.face_attributes.at("patch"));
  result.seconds.push_back({"over quads", seconds_since(start)});
  return result;
}

}  // namespace tessera::quadmesh
