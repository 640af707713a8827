#include "layout/patches.h"

#include <algorithm>

#include "base/disjoint_sets.h"

namespace tessera::layout {

std::vector<std::int32_t> assign_patches(const RefinedMesh& refined, const Connectivity& c) {
  const Mesh& mesh = refined.mesh;
  // refined.arc_edges is sorted: the edges whose smaller vertex is v are a run starting at run[v].
  std::vector<std::size_t> run(mesh.vertex_count() + 1, 0);
  for (const auto& [a, b] : refined.arc_edges) ++run[a + 1];
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) run[v + 1] += run[v];
  const auto on_arc = [&](Index a, Index b) {
    const auto [low, high] = std::minmax(a, b);
    for (std::size_t k = run[low]; k < run[low + 1]; ++k)
      if (refined.arc_edges[k].second == high) return true;
    return false;
  };
  DisjointSets sets(mesh.face_count());
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index t = c.twin[h];
    if (c.is_boundary_halfedge(t) || t < h || on_arc(c.from_vertex(h), c.to_vertex[h])) continue;
    sets.join(c.face[h], c.face[t]);
  }
  std::vector<std::int32_t> patch(mesh.face_count(), -1);
  std::vector<std::int32_t> id_of_root(mesh.face_count(), -1);
  std::int32_t next = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const std::size_t root = sets.find(f);
    if (id_of_root[root] < 0) id_of_root[root] = next++;
    patch[f] = id_of_root[root];
  }
  return patch;
}

}  // namespace tessera::layout
