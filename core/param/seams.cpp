#include "param/seams.h"

#include <array>
#include <cmath>
#include <numbers>

#include "mesh/boundary_tangents.h"
#include "mesh/geometry.h"
#include "mesh/topology.h"
#include "param/linear_elimination.h"
#include "param/poisson.h"

namespace tessera {
namespace {

// J^r as an integer matrix: column k is J^r of the k-th unit vector.
std::array<std::array<double, 2>, 2> quarter_turn_matrix(int r) {
  const Eigen::Vector2d x = quarter_turns({1, 0}, r);
  const Eigen::Vector2d y = quarter_turns({0, 1}, r);
  return {{{x.x(), y.x()}, {x.y(), y.y()}}};
}

// Rows of x(to) - J^r x(from) - t = 0, t being the two variables from `translation` on.
void add_transition(LinearElimination& elimination, Index from, Index to, int r,
                    Index translation) {
  const auto m = quarter_turn_matrix(r);
  for (Index i = 0; i < 2; ++i) {
    LinearElimination::Row row{{2 * to + i, 1.0}, {translation + i, -1.0}};
    for (Index k = 0; k < 2; ++k)
      if (m[i][k] != 0) row.emplace_back(2 * from + k, -m[i][k]);
    elimination.add(row);
  }
}

// Sec. 4.4 takes the boundary for a parameter line: along each boundary edge whose face's cross is
// aligned to the boundary curve there (alignment.h makes it so), the coordinate across the curve
// stays constant, v(b) = v(a) for a curve along u_T and u(b) = u(a) for one along v_T. The curve's
// tangent, not the edge's direction, decides (mesh/boundary_tangents.h): a staircase boundary is
// straightened into one parameter line. An edge whose curve is more than kBoundaryTolerance off
// both axes is left free.
void add_boundary_isolines(LinearElimination& elimination, const Mesh& mesh, const Connectivity& c,
                           const CrossField& combed, const Wedges& wedges) {
  const double kBoundaryTolerance = std::sin(std::numbers::pi / 6);
  const BoundaryTangents boundary = boundary_tangents(mesh, c);
  for (Index h = 0; h < c.corner_count; ++h) {
    if (!c.is_boundary_edge(c.edge[h])) continue;
    const Index f = c.face[h];
    const Eigen::Vector3d& edge = boundary.edge_tangent[c.edge[h]];
    const Eigen::Vector3d u = combed.direction[f];
    const Eigen::Vector3d v = face_normal(mesh, f).cross(u);
    const double along_u = std::abs(edge.dot(u)), along_v = std::abs(edge.dot(v));
    if (std::min(along_u, along_v) > kBoundaryTolerance) continue;
    const Index across = along_u > along_v ? 1 : 0;  // the coordinate that stays constant
    const Index a = wedges.corner_wedge[h], b = wedges.corner_wedge[c.next[h]];
    elimination.add({{2 * b + across, 1.0}, {2 * a + across, -1.0}});
  }
}

}  // namespace

Eigen::SparseMatrix<double> seam_basis(const Mesh& mesh, const Connectivity& c,
                                       const CrossField& combed,
                                       const std::vector<std::uint8_t>& cut, const Wedges& wedges) {
  std::size_t cut_count = 0;
  for (std::uint8_t x : cut) cut_count += x;
  const std::size_t wedge_variables = 2 * wedges.count;
  LinearElimination elimination(wedge_variables + 2 * cut_count);
  Index translation = static_cast<Index>(wedge_variables);
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (!cut[e]) continue;
    const Index h = c.edge_halfedge[e];
    const Index t = c.twin[h];
    const int r = combed.period_jump[h];
    const auto& w = wedges.corner_wedge;
    // h runs a -> b in f; its twin b -> a in g. Corner h sits at a, corner next(t) at a too.
    add_transition(elimination, w[h], w[c.next[t]], r, translation);
    add_transition(elimination, w[c.next[h]], w[t], r, translation);
    translation += 2;
  }
  add_boundary_isolines(elimination, mesh, c, combed, wedges);
  // The energy does not see a translation of a whole component: pin one wedge of each.
  const Components components = connected_components(mesh, c);
  std::vector<std::uint8_t> pinned(components.count, 0);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (pinned[components.face_component[f]]) continue;
    pinned[components.face_component[f]] = 1;
    const Index wedge = wedges.corner_wedge[mesh.face_offsets[f]];
    for (Index i = 0; i < 2; ++i) elimination.add({{2 * wedge + i, 1.0}});
  }
  return elimination.basis(wedge_variables);
}

Transitions seam_transitions(const Connectivity& c, const CrossField& combed,
                             const std::vector<std::uint8_t>& cut,
                             const std::vector<Eigen::Vector2d>& uv) {
  Transitions tr;
  tr.rotation.assign(c.halfedge_count(), 0);
  tr.translation.assign(c.halfedge_count(), Eigen::Vector2d::Zero());
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (!cut[e]) continue;
    const Index h = c.edge_halfedge[e];
    const Index t = c.twin[h];
    const int r = combed.period_jump[h];
    const Eigen::Vector2d shift = uv[c.next[t]] - quarter_turns(uv[h], r);
    const Eigen::Vector2d error = uv[t] - quarter_turns(uv[c.next[h]], r) - shift;
    tr.max_error = std::max(tr.max_error, error.norm());
    tr.rotation[h] = static_cast<std::uint8_t>(r);
    tr.translation[h] = shift;
    // The inverse map: uv_f = J^-r uv_g - J^-r t.
    tr.rotation[t] = static_cast<std::uint8_t>((4 - r) % 4);
    tr.translation[t] = -quarter_turns(shift, -r);
  }
  return tr;
}

}  // namespace tessera
