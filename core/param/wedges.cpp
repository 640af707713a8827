#include "param/wedges.h"

namespace tessera {
namespace {

// Rotating counterclockwise, the fan enters the face of outgoing halfedge h across h's own edge.
bool starts_wedge(const Connectivity& c, const std::vector<std::uint8_t>& cut, Index h) {
  return c.is_boundary_edge(c.edge[h]) || cut[c.edge[h]];
}

}  // namespace

Wedges cut_wedges(const Connectivity& c, const std::vector<std::uint8_t>& cut) {
  std::vector<Index> label(c.corner_count, kNoIndex);  // wedge per corner, by vertex
  for (Index v = 0; v < c.vertex_count(); ++v) {
    std::vector<Index> corners;
    for (Index h : outgoing_halfedges(c, v))
      if (!c.is_boundary_halfedge(h)) corners.push_back(h);
    std::size_t start = 0;
    while (start < corners.size() && !starts_wedge(c, cut, corners[start])) ++start;
    if (start == corners.size()) start = 0;  // no cut around v: one wedge
    Index wedge = kNoIndex;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Index h = corners[(start + i) % corners.size()];
      if (i == 0 || starts_wedge(c, cut, h)) wedge = h;  // named by a corner until renumbered
      label[h] = wedge;
    }
  }
  // Renumber 0, 1, ... in the order of each wedge's first corner.
  Wedges wedges;
  wedges.corner_wedge.assign(c.corner_count, kNoIndex);
  std::vector<Index> number(c.corner_count, kNoIndex);
  for (Index h = 0; h < c.corner_count; ++h) {
    Index& n = number[label[h]];
    if (n == kNoIndex) n = static_cast<Index>(wedges.count++);
    wedges.corner_wedge[h] = n;
  }
  return wedges;
}

}  // namespace tessera
