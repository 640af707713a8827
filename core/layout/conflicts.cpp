#include "layout/conflicts.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace tessera::layout {
namespace {

bool share_node(const GraphEdge& a, const GraphEdge& b) {
  return a.u == b.u || a.u == b.v || a.v == b.u || a.v == b.v;
}

// The arc's base direction in the chart of a piece: the piece's direction turned by the arc's
// base_turn.
bool base_along_u(const Arc& arc, const ArcPiece& piece) {
  const Eigen::Vector2d hyp = piece.to_uv - piece.from_uv;
  const Eigen::Vector2d base = std::cos(arc.base_turn) * hyp + std::sin(arc.base_turn) * perp(hyp);
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
// leave) and for which keep(arc, piece, other arc, other piece) holds; edges sharing a node left
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
    if (f % 4096 == 0) progress.step("conflicts", double(f) / double(in_face.size()));
    const auto& here = in_face[f];
    const double tolerance = charts.tolerance(f);
    for (std::size_t i = 0; i < here.size(); ++i) {
      for (std::size_t j = i + 1; j < here.size(); ++j) {
        const Arc &p = arcs[here[i].first], &q = arcs[here[j].first];
        if (p.edge == q.edge) continue;
        const GraphEdge &e = graph.edges[p.edge], &g = graph.edges[q.edge];
        if (share_node(e, g)) continue;
        const ArcPiece &a = p.pieces[here[i].second], &b = q.pieces[here[j].second];
        if (!keep(p, a, q, b) || !pieces_meet(a, b, tolerance)) continue;
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

std::vector<EdgePair> illegal_crossings(const Charts& charts, const PortGraph& graph,
                                        const std::vector<Arc>& arcs, const Progress& progress) {
  const auto same_alignment = [](const Arc& p, const ArcPiece& a, const Arc& q, const ArcPiece& b) {
    return base_along_u(p, a) == base_along_u(q, b);
  };
  std::vector<EdgePair> pairs = meeting_arcs(charts, graph, arcs, same_alignment, progress);
  pairs.insert(pairs.end(), graph.zero_area.begin(), graph.zero_area.end());
  sort_unique(pairs);
  return pairs;
}

std::vector<EdgePair> loop_pairs(const Charts& charts, const PortGraph& graph,
                                 const std::vector<Arc>& chosen) {
  const auto from_one_singularity = [&graph](const Arc& p, const ArcPiece&, const Arc& q,
                                             const ArcPiece&) {
    return share_singularity(graph, graph.edges[p.edge], graph.edges[q.edge]);
  };
  std::vector<EdgePair> pairs =
      meeting_arcs(charts, graph, chosen, from_one_singularity, Progress());
  const std::vector<EdgePair> joining = joining_same_singularities(graph, chosen);
  pairs.insert(pairs.end(), joining.begin(), joining.end());
  sort_unique(pairs);
  return pairs;
}

}  // namespace tessera::layout
