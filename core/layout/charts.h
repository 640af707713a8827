// The atlas of M_f as the layout stage sees it (LAYOUT_NOTES "Charts and transitions", thesis
// Def. 2.2, (2.2)): every triangle is a chart with the (u, v) of its three corners; across an
// interior edge the charts differ by phi(p) = J^r p + t, r in Z4. Since every transition is a rigid
// motion, parametric lengths and angles are the same in every chart.
//
// In:  a triangle mesh, its connectivity, and a seamless parameterization of it (all outlive the
//      Charts value, which only refers to them).
// Out: per-face chart access, transitions of points and directions, the chart tolerance.
#pragma once

#include <Eigen/Core>

#include "mesh/connectivity.h"
#include "mesh/mesh.h"
#include "param/seamless_param.h"

namespace tessera::layout {

struct Charts {
  const Mesh& mesh;
  const Connectivity& connectivity;
  const SeamlessParam& param;

  // (u, v) of corner h in the chart of face(h).
  const Eigen::Vector2d& uv(Index h) const { return param.uv[h]; }
  // A direction of the chart of face(h) in the chart of face(twin h).
  Eigen::Vector2d direction_across(Index h, const Eigen::Vector2d& d) const;
  // The point at parameter t along corner halfedge h (from its corner to the next) in face(h).
  Eigen::Vector2d point_on_halfedge(Index h, double t) const;
  // Twice the signed area of face f in its chart (negative: the chart is flipped).
  double signed_area(Index f) const;
  // Lengths below this are zero in face f: 1e-9 times its longest chart edge. Orientation tests
  // against a unit direction use it, so that a line through a vertex is seen as such in every face.
  double tolerance(Index f) const;
  // The vertex of corner h and the corners of face f.
  Index vertex(Index h) const { return mesh.face_vertices[h]; }
  Index first_corner(Index f) const { return mesh.face_offsets[f]; }
};

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b);
// The counterclockwise quarter turn J x.
inline Eigen::Vector2d perp(const Eigen::Vector2d& x) {
  return {-x.y(), x.x()};
}

}  // namespace tessera::layout
