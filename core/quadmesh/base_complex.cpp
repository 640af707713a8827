#include "quadmesh/base_complex.h"

#include "base/disjoint_sets.h"
#include "base/error.h"
#include "quadmesh/integer_charts.h"

namespace tessera::quadmesh {
namespace {

bool is_irregular(const Connectivity& c, const std::vector<int>& valence, Index v) {
  return valence[v] != (c.is_boundary_vertex(v) ? 2 : 4);
}

BaseLine trace_line(const Connectivity& c, const std::vector<int>& valence, Index first) {
  BaseLine line;
  Index h = first;
  // A line never passes one halfedge twice (straight_on() is one-to-one and the line starts at a
  // vertex it cannot come back through), so it ends within this many steps.
  for (std::size_t steps = 0; steps <= c.halfedge_count(); ++steps) {
    line.halfedges.push_back(h);
    const Index head = c.to_vertex[h];
    if (is_irregular(c, valence, head)) {
      line.end = LineEnd::singularity;
      return line;
    }
    if (c.is_boundary_vertex(head)) {
      line.end = LineEnd::boundary;
      return line;
    }
    h = straight_on(c, valence, h);
  }
  throw Error("trivial_base_complex(): a separatrix does not end");
}

// Quads joined across every edge that is neither on B nor on the boundary, numbered in the order
// of each patch's first quad.
std::vector<std::int32_t> patches_of(const Mesh& quads, const Connectivity& c,
                                     const std::vector<std::uint8_t>& on_b, std::size_t& count) {
  DisjointSets sets(quads.face_count());
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (on_b[e] || c.is_boundary_edge(e)) continue;
    const Index h = c.edge_halfedge[e];
    sets.join(c.face[h], c.face[c.twin[h]]);
  }
  std::vector<std::int32_t> patch(quads.face_count(), -1);
  std::vector<std::int32_t> id_of_root(quads.face_count(), -1);
  count = 0;
  for (std::size_t f = 0; f < quads.face_count(); ++f) {
    std::int32_t& id = id_of_root[sets.find(f)];
    if (id < 0) id = static_cast<std::int32_t>(count++);
    patch[f] = id;
  }
  return patch;
}

}  // namespace

Index straight_on(const Connectivity& c, const std::vector<int>& valence, Index h) {
  const Index head = c.to_vertex[h];
  if (valence[head] != 4 || c.is_boundary_vertex(head) || c.is_boundary_halfedge(h))
    return kNoIndex;
  // next[h] turns left at the head; across that edge, the next halfedge turns left again from
  // the way back: straight on.
  return c.next[c.twin[c.next[h]]];
}

BaseComplex trivial_base_complex(const Mesh& quads, const Connectivity& c) {
  const std::vector<int> valence = quad_valences(quads);
  BaseComplex b;
  b.line_of_halfedge.assign(c.halfedge_count(), kNoIndex);
  b.on_b.assign(c.edge_count(), 0);
  std::vector<Index> outgoing;
  for (Index v = 0; v < quads.vertex_count(); ++v) {
    if (!is_irregular(c, valence, v)) continue;
    outgoing_halfedges(c, v, outgoing);
    for (Index h : outgoing) {
      if (c.is_boundary_edge(c.edge[h])) continue;
      b.line_of_halfedge[h] = static_cast<Index>(b.lines.size());
      b.lines.push_back(trace_line(c, valence, h));
      for (Index step : b.lines.back().halfedges) b.on_b[c.edge[step]] = 1;
    }
  }
  b.patch = patches_of(quads, c, b.on_b, b.patch_count);
  b.check = layout::check_layout(quads, c, b.patch);
  return b;
}

}  // namespace tessera::quadmesh
