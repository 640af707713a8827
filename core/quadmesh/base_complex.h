// The trivial base complex B of a quad mesh (thesis Sec. 7.2, 7.3 step 1): every discrete
// parameter line leaving an irregular vertex along one of its interior edges, traced edge by edge
// straight on through the regular vertices (at an interior vertex of valence 4 the edge opposite
// the one it came along) until it reaches an irregular vertex or the boundary. The union of these
// separatrices, with the boundary, cuts the mesh into the patches of B, each a grid of quads.
//
// Each separatrix between two irregular vertices is traced from both ends (two lines running
// opposite ways: the open separatrices of both ports, which the supergraph needs, Sec. 7.4).
//
// In:  a pure quad mesh (quad_input.h) and its connectivity. Out: the lines, per mesh edge whether
//      B holds it, per quad its patch of B, and the project's layout check of those patches.
#pragma once

#include <cstdint>
#include <vector>

#include "layout/layout_check.h"
#include "mesh/connectivity.h"
#include "mesh/mesh.h"

namespace tessera::quadmesh {

enum class LineEnd : std::uint8_t { singularity, boundary };

struct BaseLine {
  std::vector<Index> halfedges;  // of the quad mesh, in order from the irregular vertex
  LineEnd end = LineEnd::singularity;
  std::size_t length() const { return halfedges.size(); }  // in the integer metric
};

struct BaseComplex {
  std::vector<BaseLine> lines;          // one per interior edge leaving an irregular vertex
  std::vector<Index> line_of_halfedge;  // per halfedge: the line starting with it, or kNoIndex
  std::vector<std::uint8_t> on_b;       // per edge: a separatrix of B runs along it
  std::vector<std::int32_t> patch;      // per quad
  std::size_t patch_count = 0;
  layout::LayoutCheck check;
};

// The halfedge leaving the head of `h` straight on, if that vertex is regular and interior
// (kNoIndex otherwise).
Index straight_on(const Connectivity& connectivity, const std::vector<int>& valence, Index h);

BaseComplex trivial_base_complex(const Mesh& quads, const Connectivity& connectivity);

}  // namespace tessera::quadmesh
