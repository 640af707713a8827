#include "quadopt/repair.h"

#include <algorithm>

#include "layout/conflicts.h"

namespace tessera::quadopt {
namespace {

bool share_a_node(const layout::GraphEdge& a, const layout::GraphEdge& b) {
  return a.u == b.u || a.u == b.v || a.v == b.u || a.v == b.v;
}

// Per patch that is no disk with four corners, the positions (in failed.arcs, as in
// failed.matching.edges) of the chosen arcs
// passing a face of it or a vertex of such a face.
std::vector<std::vector<std::size_t>> arcs_near_bad_patches(const layout::Charts& charts,
                                                            const layout::QuadLayout& failed) {
  const Mesh& mesh = charts.mesh;
  std::vector<std::vector<std::size_t>> arcs_at_vertex(mesh.vertex_count());
  for (std::size_t k = 0; k < failed.arcs.size(); ++k)
    for (const layout::ArcPiece& piece : failed.arcs[k].pieces)
      for (Index v : mesh.face(piece.face)) {
        std::vector<std::size_t>& here = arcs_at_vertex[v];
        if (here.empty() || here.back() != k) here.push_back(k);
      }
  const auto& patch = failed.refined.mesh.face_attributes.at("patch");
  const layout::LayoutCheck& check = failed.check;
  std::vector<std::vector<std::size_t>> near(check.patch_count);
  for (Index f = 0; f < failed.refined.mesh.face_count(); ++f) {
    const std::int32_t p = patch[f];
    if (p < 0 || std::size_t(p) >= check.patch_count || check.corners[p].size() == 4) continue;
    for (Index v : mesh.face(failed.refined.parent[f]))
      near[p].insert(near[p].end(), arcs_at_vertex[v].begin(), arcs_at_vertex[v].end());
  }
  for (std::vector<std::size_t>& arcs : near) {
    std::sort(arcs.begin(), arcs.end());
    arcs.erase(std::unique(arcs.begin(), arcs.end()), arcs.end());
  }
  return near;
}

}  // namespace

std::vector<layout::EdgePair> quad_repair_pairs(const layout::Charts& charts,
                                                const layout::PortGraph& graph,
                                                const layout::QuadLayout& failed) {
  std::vector<layout::EdgePair> pairs = layout::loop_pairs(charts, graph, failed.arcs);
  if (failed.check.corners.size() == failed.check.patch_count) {
    for (const std::vector<std::size_t>& arcs : arcs_near_bad_patches(charts, failed)) {
      for (std::size_t i = 0; i < arcs.size(); ++i)
        for (std::size_t j = i + 1; j < arcs.size(); ++j) {
          const Index a = failed.matching.edges[arcs[i]], b = failed.matching.edges[arcs[j]];
          const layout::GraphEdge &ea = graph.edges[a], &eb = graph.edges[b];
          if (share_a_node(ea, eb)) continue;
          if (ea.kind != layout::EdgeKind::crossing && eb.kind != layout::EdgeKind::crossing)
            continue;
          pairs.push_back({std::min(a, b), std::max(a, b)});
        }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace tessera::quadopt
