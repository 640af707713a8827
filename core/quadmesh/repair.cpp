#include "quadmesh/repair.h"

#include <algorithm>
#include <optional>

#include "layout/arcs.h"
#include "layout/conflicts.h"

namespace tessera::quadmesh {
namespace {

bool share_a_node(const layout::GraphEdge& a, const layout::GraphEdge& b) {
  return a.u == b.u || a.u == b.v || a.v == b.u || a.v == b.v;
}

// What a failed round left: per faulty patch (no disk, not four corners, or touching itself) the
// input faces it covers, and the positions (in failed.arcs, as in failed.matching.edges) of the
// chosen arcs passing one of those faces or a vertex of one.
struct FaultyPatches {
  std::vector<std::vector<Index>> faces;
  std::vector<std::vector<std::size_t>> arcs;
};

void sort_unique(std::vector<std::size_t>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
}

FaultyPatches faulty_patches(const layout::Charts& charts, const layout::QuadLayout& failed) {
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
  std::vector<std::int32_t> slot(check.patch_count, -1);
  FaultyPatches result;
  for (std::int32_t p : check.faulty_patches)
    slot[p] = std::int32_t(result.faces.size()), result.faces.emplace_back();
  result.arcs.resize(result.faces.size());
  for (Index f = 0; f < failed.refined.mesh.face_count(); ++f) {
    const std::int32_t p = patch[f];
    if (p < 0 || std::size_t(p) >= check.patch_count || slot[p] < 0) continue;
    const Index parent = failed.refined.parent[f];
    result.faces[slot[p]].push_back(parent);
    for (Index v : mesh.face(parent))
      result.arcs[slot[p]].insert(result.arcs[slot[p]].end(), arcs_at_vertex[v].begin(),
                                  arcs_at_vertex[v].end());
  }
  for (std::vector<std::size_t>& arcs : result.arcs) sort_unique(arcs);
  for (std::vector<Index>& faces : result.faces) {
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  }
  return result;
}

// The chosen crossing edges that took the ports of the separatrices of B (not chosen) that run
// through a faulty patch: without them B's separatrix would cut across it (an annulus around a
// handle bounded by separatrices of B alone has no crossing edge near it).
std::vector<Index> edges_that_took_cuts(const layout::Charts& charts,
                                        const layout::PortGraph& graph,
                                        const layout::QuadLayout& failed,
                                        const std::vector<Index>& faces) {
  std::vector<Index> chosen_at(graph.node_count(), kNoIndex);
  std::vector<std::uint8_t> chosen(graph.edges.size(), 0);
  for (Index e : failed.matching.edges) {
    chosen[e] = 1;
    chosen_at[graph.edges[e].u] = chosen_at[graph.edges[e].v] = e;
  }
  std::vector<Index> result;
  for (Index e = 0; e < graph.edges.size(); ++e) {
    const layout::GraphEdge& edge = graph.edges[e];
    if (chosen[e] || edge.kind == layout::EdgeKind::crossing) continue;
    const std::optional<layout::Arc> arc = layout::trace_arc(charts, graph, e);
    if (!arc) continue;
    bool through = false;
    for (const layout::ArcPiece& piece : arc->pieces)
      through = through || std::binary_search(faces.begin(), faces.end(), piece.face);
    if (!through) continue;
    for (Index node : {edge.u, edge.v}) {
      const Index taker = chosen_at[node];
      if (taker != kNoIndex && graph.edges[taker].kind == layout::EdgeKind::crossing)
        result.push_back(taker);
    }
  }
  return result;
}

}  // namespace

std::vector<layout::EdgePair> quad_repair_pairs(const layout::Charts& charts,
                                                const layout::PortGraph& graph,
                                                const layout::QuadLayout& failed) {
  std::vector<layout::EdgePair> pairs;
  const auto add = [&](Index a, Index b) {
    const layout::GraphEdge &ea = graph.edges[a], &eb = graph.edges[b];
    if (a == b || share_a_node(ea, eb)) return;
    if (ea.kind != layout::EdgeKind::crossing && eb.kind != layout::EdgeKind::crossing) return;
    pairs.push_back({std::min(a, b), std::max(a, b)});
  };
  // Two separatrices of B may well close a loop (a helix, Fig. 7.3): B keeps them.
  for (const layout::EdgePair& pair : layout::loop_pairs(charts, graph, failed.arcs))
    add(pair.first, pair.second);
  if (failed.check.corners.size() == failed.check.patch_count) {  // the patch ids cover the faces
    const FaultyPatches faulty = faulty_patches(charts, failed);
    for (std::size_t k = 0; k < faulty.arcs.size(); ++k) {
      std::vector<Index> near;
      for (std::size_t position : faulty.arcs[k]) near.push_back(failed.matching.edges[position]);
      const std::size_t before = pairs.size();
      for (std::size_t i = 0; i < near.size(); ++i)
        for (std::size_t j = i + 1; j < near.size(); ++j) add(near[i], near[j]);
      if (pairs.size() > before) continue;
      for (Index taker : edges_that_took_cuts(charts, graph, failed, faulty.faces[k]))
        for (Index e : near) add(taker, e);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace tessera::quadmesh
