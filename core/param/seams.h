// Seamlessness across the cut graph (Sec. 6.6, (6.6); App. A, (A.7), (A.8)). Across a cut edge
// from face f to face g with combed period jump r, the charts are related by the transition
//   uv_g = J^r uv_f + t
// at both ends of the edge: the rotation is the field's, the translation t is free (the "open"
// parameterization of Sec. 2.1; it is not rounded to integers). Across uncut edges the combed
// charts agree (r = 0, t = 0) because both faces share the wedges. Boundary edges are parameter
// lines (Sec. 4.4): the coordinate across each one is constant along it.
//
// In:  mesh, connectivity, combed field, cut edges and wedges of the same mesh.
// Out: the basis P (wedge variables = P y, poisson.h's variable order) in which every transition
//      and boundary constraint holds and one wedge per connected component is pinned to (0, 0);
//      afterwards the transitions themselves. Nothing throws.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Sparse>

#include "field/cross_field.h"
#include "param/wedges.h"

namespace tessera {

Eigen::SparseMatrix<double> seam_basis(const Mesh& mesh, const Connectivity& connectivity,
                                       const CrossField& combed,
                                       const std::vector<std::uint8_t>& cut, const Wedges& wedges);

struct Transitions {
  std::vector<std::uint8_t> rotation;  // per halfedge h: r_h in Z4 from face(h) to its twin's
  std::vector<Eigen::Vector2d>
      translation;       // per halfedge: t_h; (0, 0) on uncut and boundary edges
  double max_error = 0;  // largest |uv_g - (J^r uv_f + t)| over the cut edges' ends (absolute)
};

// The transitions of per-corner uv: t from each cut edge's first end, the error at both ends.
Transitions seam_transitions(const Connectivity& connectivity, const CrossField& combed,
                             const std::vector<std::uint8_t>& cut,
                             const std::vector<Eigen::Vector2d>& uv);

}  // namespace tessera
