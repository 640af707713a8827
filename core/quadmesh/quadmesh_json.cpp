#include "quadmesh/quadmesh_json.h"

#include <cmath>

namespace tessera::quadmesh {
namespace {

nlohmann::ordered_json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json quad_layout_json(const QuadGraph& graph, const QuadLayoutResult& result,
                                        bool diagonals) {
  const layout::PortGraph& g = graph.layout_graph.graph;
  const layout::QuadLayout& layout = result.layout;
  const Supergraph& s = graph.supergraph;
  nlohmann::ordered_json json;
  json["singularities"] = g.ports.points.size();
  json["base_complex_patches"] = graph.base.patch_count;
  json["patches"] = result.check.patch_count;
  json["angle_rsd"] = layout.angle_rsd;
  json["graph_edges"] = g.edges.size();
  json["conflicts"] = g.conflicts.size();
  json["matching_status"] = matching::to_string(layout.matching.status);
  nlohmann::ordered_json seconds = nlohmann::ordered_json::object();
  double total = 0;
  for (const auto* stages : {&graph.layout_graph.seconds, &result.seconds})
    for (const layout::StageSeconds& stage : *stages) {
      seconds[stage.stage] = stage.seconds;
      total += stage.seconds;
    }
  seconds["total"] = total;
  json["seconds"] = seconds;
  json["quads"] = graph.quads.face_count();
  json["valid"] = result.check.valid();
  json["base_complex_valid"] = graph.base.check.valid();
  json["objective"] = finite_or_null(layout.matching.objective);
  json["lower_bound"] = finite_or_null(layout.matching.lower_bound);
  json["matching_stopped_by"] =
      layout.matching.stopped_by == matching::StopReason::none
          ? nlohmann::ordered_json(nullptr)
          : nlohmann::ordered_json(matching::to_string(layout.matching.stopped_by));
  json["alpha"] = layout.alpha;
  json["diagonals"] = diagonals;
  json["ports"] = g.port_count();
  json["virtual_ports"] = g.virtual_ports.size();
  json["separatrix_edges"] = s.separatrix_edges;
  json["crossing_edges"] = s.crossing_edges;
  json["diagonal_edges"] = s.diagonal_edges;
  json["zero_area_pairs"] = g.zero_area.size();
  json["rejected_by_window"] = s.rejected_by_window;
  json["curved_edges"] = graph.layout_graph.curved_edges;
  json["twin_edges"] = graph.layout_graph.twin_edges;
  json["cut_quads"] = result.cut_quads;
  json["rounds"] = layout.rounds();
  json["p1_nodes"] = layout.p1_nodes;
  std::vector<std::string> problems = result.check.problems;
  if (problems.empty()) problems = layout.check.problems;
  json["problems"] = problems;
  json["problem_count"] = std::max(result.check.problem_count, layout.check.problem_count);
  return json;
}

}  // namespace tessera::quadmesh
