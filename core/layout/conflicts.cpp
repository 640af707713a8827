#include "layout/conflicts.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace tessera::layout {
namespace {

enum class Role { base, height };

struct EdgeOnLine {
  Index edge = 0;
  Role role = Role::base;
};

// One pass of a separatrix through the frame point m: its length there and direction in the chart.
struct Pass {
  Eigen::Vector2d point;
  double length = 0;
  Eigen::Vector2d direction;
};

// An edge's hypotenuse laid out in a frame, and whether its base is parallel to the frame's first
// pass (x-aligned) or to the second (y-aligned).
struct Hypotenuse {
  Index edge = 0;
  Eigen::Vector2d from;
  Eigen::Vector2d to;
  bool x_aligned = false;
};

std::vector<std::vector<EdgeOnLine>> edges_by_line(const PortGraph& graph) {
  std::vector<std::vector<EdgeOnLine>> by_line(graph.separatrices.size());
  for (Index e = 0; e < graph.edges.size(); ++e) {
    const GraphEdge& edge = graph.edges[e];
    by_line[edge.base_line].push_back({e, Role::base});
    if (edge.height_line != kNoIndex) by_line[edge.height_line].push_back({e, Role::height});
  }
  return by_line;
}

// The triangle of `edge` walked out from the pass: along the line, unit speed, straight.
Hypotenuse lay_out(const GraphEdge& edge, Index index, Role role, const Pass& pass,
                   bool pass_is_x) {
  const Eigen::Vector2d& d = pass.direction;
  const Eigen::Vector2d line_start = pass.point - pass.length * d;
  Hypotenuse h;
  h.edge = index;
  if (role == Role::base) {
    const Eigen::Vector2d m = pass.point + (edge.base - pass.length) * d;
    h.from = line_start;
    h.to = m - edge.height * edge.side * perp(d);
    h.x_aligned = pass_is_x;
  } else {
    const Eigen::Vector2d m = pass.point + (edge.height - pass.length) * d;
    const Eigen::Vector2d d_base = -edge.side * perp(d);
    h.from = m - edge.base * d_base;
    h.to = line_start;
    h.x_aligned = !pass_is_x;
  }
  return h;
}

// Proper crossing of two segments: each has the other's endpoints strictly on opposite sides.
bool segments_cross(const Hypotenuse& p, const Hypotenuse& q) {
  const Eigen::Vector2d dp = p.to - p.from, dq = q.to - q.from;
  const double tolerance = 1e-9 * std::max({1.0, dp.squaredNorm(), dq.squaredNorm()});
  const auto strictly_apart = [tolerance](double s, double t) {
    return (s > tolerance && t < -tolerance) || (s < -tolerance && t > tolerance);
  };
  return strictly_apart(cross(dp, q.from - p.from), cross(dp, q.to - p.from)) &&
         strictly_apart(cross(dq, p.from - q.from), cross(dq, p.to - q.from));
}

bool share_node(const GraphEdge& a, const GraphEdge& b) {
  return a.u == b.u || a.u == b.v || a.v == b.u || a.v == b.v;
}

std::vector<Hypotenuse> lay_out_line(const PortGraph& graph, const std::vector<EdgeOnLine>& on_line,
                                     const Pass& pass, bool pass_is_x) {
  std::vector<Hypotenuse> result;
  result.reserve(on_line.size());
  for (const EdgeOnLine& e : on_line)
    result.push_back(lay_out(graph.edges[e.edge], e.edge, e.role, pass, pass_is_x));
  return result;
}

// The arc's base direction in the chart of a piece: the piece's direction turned back by the
// hypotenuse's angle with the base (arcs run from the base port's singularity).
bool base_along_u(const GraphEdge& edge, const ArcPiece& piece) {
  const Eigen::Vector2d hyp = piece.to_uv - piece.from_uv;
  const double turn = std::atan2(edge.side * edge.height, edge.base);
  const Eigen::Vector2d base = std::cos(turn) * hyp + std::sin(turn) * perp(hyp);
  return std::abs(base.x()) > std::abs(base.y());
}

// Two pieces in one chart meet: their segments intersect, touching included (a crossing on a mesh
// edge is an endpoint of the pieces on both sides).
bool pieces_meet(const ArcPiece& p, const ArcPiece& q, double tolerance) {
  const Eigen::Vector2d dp = p.to_uv - p.from_uv, dq = q.to_uv - q.from_uv;
  const auto side = [tolerance](double s) { return s > tolerance ? 1 : s < -tolerance ? -1 : 0; };
  const int a = side(cross(dp, q.from_uv - p.from_uv)), b = side(cross(dp, q.to_uv - p.from_uv));
  const int c = side(cross(dq, p.from_uv - q.from_uv)), d = side(cross(dq, p.to_uv - q.from_uv));
  if (a * b > 0 || c * d > 0) return false;
  return !(a == 0 && b == 0);  // collinear pieces do not cross
}

Index singular_point_of(const PortGraph& graph, Index node) {
  return graph.is_virtual(node) ? kNoIndex : graph.ports.ports[node].singular_point;
}

// The two edges have an end at the same singularity.
bool share_singularity(const PortGraph& graph, const GraphEdge& a, const GraphEdge& b) {
  for (Index x : {a.u, a.v}) {
    const Index s = singular_point_of(graph, x);
    if (s != kNoIndex && (s == singular_point_of(graph, b.u) || s == singular_point_of(graph, b.v)))
      return true;
  }
  return false;
}

bool at_singular_vertex(const PortGraph& graph, const SurfacePoint& a, const SurfacePoint& b) {
  return a.vertex != kNoIndex && a == b && graph.ports.point_of_vertex[a.vertex] != kNoIndex;
}

}  // namespace

namespace {

void sort_unique(std::vector<EdgePair>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

// The pairs of arcs whose pieces meet in a face (touching included, but not at a singularity both
// leave) and for which keep(edge, piece, other edge, other piece) holds; edges sharing a node left
// out.
template <class Keep>
std::vector<EdgePair> meeting_arcs(const Charts& charts, const PortGraph& graph,
                                   const std::vector<Arc>& arcs, const Keep& keep,
                                   const Progress& progress) {
  std::vector<std::vector<std::pair<Index, Index>>> in_face(charts.mesh.face_count());
  for (Index a = 0; a < arcs.size(); ++a)
    for (Index k = 0; k < arcs[a].pieces.size(); ++k)
      in_face[arcs[a].pieces[k].face].push_back({a, k});
  std::vector<EdgePair> pairs;
  for (Index f = 0; f < in_face.size(); ++f) {
    if (f % 4096 == 0) progress.step("arc crossings", double(f) / double(in_face.size()));
    const auto& here = in_face[f];
    const double tolerance = charts.tolerance(f);
    for (std::size_t i = 0; i < here.size(); ++i) {
      for (std::size_t j = i + 1; j < here.size(); ++j) {
        const Arc &p = arcs[here[i].first], &q = arcs[here[j].first];
        if (p.edge == q.edge) continue;
        const GraphEdge &e = graph.edges[p.edge], &g = graph.edges[q.edge];
        if (share_node(e, g)) continue;
        const ArcPiece &a = p.pieces[here[i].second], &b = q.pieces[here[j].second];
        if (!keep(e, a, g, b) || !pieces_meet(a, b, tolerance)) continue;
        if (at_singular_vertex(graph, a.from, b.from) || at_singular_vertex(graph, a.from, b.to) ||
            at_singular_vertex(graph, a.to, b.from) || at_singular_vertex(graph, a.to, b.to))
          continue;
        pairs.push_back({std::min(p.edge, q.edge), std::max(p.edge, q.edge)});
      }
    }
  }
  sort_unique(pairs);
  return pairs;
}

std::vector<EdgePair> joining_same_singularities(const PortGraph& graph,
                                                 const std::vector<Arc>& arcs) {
  std::map<std::pair<Index, Index>, std::vector<Index>> joining;
  for (const Arc& arc : arcs) {
    const Index s = singular_point_of(graph, graph.edges[arc.edge].u);
    const Index t = singular_point_of(graph, graph.edges[arc.edge].v);
    if (s != kNoIndex && t != kNoIndex && s != t) joining[std::minmax(s, t)].push_back(arc.edge);
  }
  std::vector<EdgePair> pairs;
  for (const auto& [ends, edges] : joining)
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = i + 1; j < edges.size(); ++j)
        pairs.push_back({std::min(edges[i], edges[j]), std::max(edges[i], edges[j])});
  return pairs;
}

}  // namespace

std::vector<EdgePair> illegal_arc_crossings(const Charts& charts, const PortGraph& graph,
                                            const std::vector<Arc>& arcs,
                                            const Progress& progress) {
  const auto same_alignment = [](const GraphEdge& e, const ArcPiece& a, const GraphEdge& g,
                                 const ArcPiece& b) {
    return base_along_u(e, a) == base_along_u(g, b);
  };
  return meeting_arcs(charts, graph, arcs, same_alignment, progress);
}

std::vector<EdgePair> loop_pairs(const Charts& charts, const PortGraph& graph,
                                 const std::vector<Arc>& chosen) {
  const auto from_one_singularity = [&graph](const GraphEdge& e, const ArcPiece&,
                                             const GraphEdge& g, const ArcPiece&) {
    return share_singularity(graph, e, g);
  };
  std::vector<EdgePair> pairs =
      meeting_arcs(charts, graph, chosen, from_one_singularity, Progress());
  const std::vector<EdgePair> joining = joining_same_singularities(graph, chosen);
  pairs.insert(pairs.end(), joining.begin(), joining.end());
  sort_unique(pairs);
  return pairs;
}

std::vector<EdgePair> illegal_crossings(const PortGraph& graph, const Progress& progress) {
  const std::vector<std::vector<EdgeOnLine>> by_line = edges_by_line(graph);
  std::vector<EdgePair> pairs = graph.zero_area;
  for (std::size_t k = 0; k < graph.crossings.size(); ++k) {
    if (k % 256 == 0) progress.step("conflicts", double(k) / graph.crossings.size());
    const Crossing& m = graph.crossings[k];
    const std::vector<Hypotenuse> on_a =
        lay_out_line(graph, by_line[m.line_a], {m.point, m.length_a, m.direction_a}, true);
    const std::vector<Hypotenuse> on_b =
        lay_out_line(graph, by_line[m.line_b], {m.point, m.length_b, m.direction_b}, false);
    for (const Hypotenuse& p : on_a) {
      for (const Hypotenuse& q : on_b) {
        if (p.edge == q.edge || p.x_aligned != q.x_aligned) continue;
        if (share_node(graph.edges[p.edge], graph.edges[q.edge])) continue;
        if (segments_cross(p, q))
          pairs.push_back({std::min(p.edge, q.edge), std::max(p.edge, q.edge)});
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace tessera::layout
