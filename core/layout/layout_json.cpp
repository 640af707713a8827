#include "layout/layout_json.h"

#include <algorithm>
#include <cmath>

namespace tessera::layout {
namespace {

// JSON has no infinity: a missing bound or objective is null.
nlohmann::ordered_json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}

// The vertices of the singularities whose ring the parameterization folds (ports.h): a port starts
// in a flipped triangle, or fewer ports than the valence leave the vertex.
std::vector<Index> folded_singularities(const Ports& ports) {
  std::vector<Index> vertices;
  for (const SingularPoint& point : ports.points) {
    bool folded = point.cyclic() && point.ports.size() != std::size_t(point.valence);
    for (Index port : point.ports) folded = folded || ports.ports[port].folded;
    if (folded) vertices.push_back(point.ring.vertex);
  }
  return vertices;
}

}  // namespace

nlohmann::ordered_json layout_json(const LayoutGraph& graph, const QuadLayout& layout) {
  const PortGraph& g = graph.graph;
  nlohmann::ordered_json json;
  const std::size_t stand_ins =
      std::count_if(g.ports.points.begin(), g.ports.points.end(),
                    [](const SingularPoint& point) { return point.stand_in(); });
  json["singularities"] = g.ports.points.size() - stand_ins;
  json["stand_in_nodes"] = stand_ins;
  json["graph_edges"] = g.edges.size();
  json["conflicts"] = g.conflicts.size();
  json["patches"] = layout.check.patch_count;
  json["angle_rsd"] = layout.angle_rsd;
  json["valid"] = layout.check.valid();
  json["objective"] = finite_or_null(layout.matching.objective);
  nlohmann::ordered_json seconds = nlohmann::ordered_json::object();
  for (const StageSeconds& s : graph.seconds) seconds[s.stage] = s.seconds;
  for (const StageSeconds& s : layout.seconds) seconds[s.stage] = s.seconds;
  json["seconds"] = seconds;
  json["alpha"] = layout.alpha;
  json["ports"] = g.port_count();
  json["virtual_ports"] = g.virtual_ports.size();
  json["nodes"] = layout.check.nodes.size();
  json["arcs"] = layout.check.arcs.size();
  json["solver"] = matching::to_string(layout.solver);
  json["matching_status"] = matching::to_string(layout.matching.status);
  json["matching_stopped_by"] =
      layout.matching.stopped_by == matching::StopReason::none
          ? nlohmann::ordered_json(nullptr)
          : nlohmann::ordered_json(matching::to_string(layout.matching.stopped_by));
  json["p1_nodes"] = layout.p1_nodes;
  json["lower_bound"] = finite_or_null(layout.matching.lower_bound);
  json["curved_edges"] = graph.curved_edges;
  json["twin_edges"] = graph.twin_edges;
  std::size_t loop_conflicts = 0;
  for (const std::vector<EdgePair>& round : layout.loop_rounds) loop_conflicts += round.size();
  json["loop_conflicts"] = loop_conflicts;
  json["rounds"] = layout.rounds();
  json["reused_rounds"] = layout.reused_rounds;
  json["solved_before"] = layout.solved_before;
  json["trace_steps"] = graph.trace_steps;
  json["trace_crossings"] = graph.trace_crossings;
  json["length_limit"] = g.length_limit;
  json["length_doublings"] = graph.length_doublings;
  json["unmatchable_ports"] = graph.unmatchable_ports;
  json["folded_singularities"] = folded_singularities(g.ports);
  json["average_separatrix_length"] = average_separatrix_length(g);
  json["problems"] = layout.check.problems;
  json["problem_count"] = layout.check.problem_count;
  return json;
}

}  // namespace tessera::layout
