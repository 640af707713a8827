#include "field/alignment.h"

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "mesh/boundary_tangents.h"
#include "mesh/geometry.h"

namespace tessera {
namespace {

// Least-squares shape operator [a b; b c] of face f in its frame: it maps each edge vector to the
// change of the normal along that edge.
Eigen::Vector3d shape_operator(const Mesh& mesh, const FaceFrames& frames,
                               const std::vector<Eigen::Vector3d>& normals, Index f) {
  const auto v = mesh.face(f);
  Eigen::Matrix<double, 6, 3> m = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 6, 1> rhs;
  for (int i = 0; i < 3; ++i) {
    const Index from = v[i];
    const Index to = v[(i + 1) % 3];
    const Eigen::Vector2d e = frames.local(f, mesh.positions[to] - mesh.positions[from]);
    const Eigen::Vector2d dn = frames.local(f, normals[to] - normals[from]);
    m.row(2 * i) << e.x(), e.y(), 0;
    m.row(2 * i + 1) << 0, e.x(), e.y();
    rhs.segment<2>(2 * i) = dn;
  }
  return (m.transpose() * m).ldlt().solve(m.transpose() * rhs);
}

// Interior edges sharper than the threshold that continue in another sharp edge at one of their
// ends: a feature is a line of sharp edges, a lone sharp edge is noise of the tessellation.
std::vector<std::uint8_t> feature_edges(const Connectivity& c, const std::vector<double>& dihedral,
                                        double sharp_radians) {
  std::vector<std::uint8_t> sharp(c.edge_count(), 0);
  std::vector<Index> count(c.vertex_count(), 0);
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (c.is_boundary_edge(e) || std::abs(dihedral[e]) <= sharp_radians) continue;
    sharp[e] = 1;
    const Index h = c.edge_halfedge[e];
    ++count[c.from_vertex(h)];
    ++count[c.to_vertex[h]];
  }
  for (Index e = 0; e < c.edge_count(); ++e) {
    const Index h = c.edge_halfedge[e];
    if (sharp[e] && count[c.from_vertex(h)] < 2 && count[c.to_vertex[h]] < 2) sharp[e] = 0;
  }
  return sharp;
}

// The other sharp edge at vertex v, if v continues the feature line in exactly one edge besides e.
Index continuation(const Connectivity& c, const std::vector<std::uint8_t>& sharp, Index v,
                   Index e) {
  Index other = kNoIndex;
  for (Index h : outgoing_halfedges(c, v)) {
    if (!sharp[c.edge[h]] || c.edge[h] == e) continue;
    if (other != kNoIndex) return kNoIndex;  // a corner of the feature graph
    other = h;
  }
  return other == kNoIndex ? kNoIndex : c.to_vertex[other];
}

// Direction of the feature line along sharp halfedge h: the chord over h and the sharp edges that
// continue it at both ends. On a triangulation a feature line zigzags; the chord follows the line,
// not the zigzag, so that neighbouring faces do not get constraints at needlessly different angles.
Eigen::Vector3d feature_tangent(const Mesh& mesh, const Connectivity& c,
                                const std::vector<std::uint8_t>& sharp, Index h) {
  Index from = c.from_vertex(h);
  Index to = c.to_vertex[h];
  const Index before = continuation(c, sharp, from, c.edge[h]);
  const Index after = continuation(c, sharp, to, c.edge[h]);
  if (before != kNoIndex && before != to) from = before;
  if (after != kNoIndex && after != from) to = after;
  return mesh.positions[to] - mesh.positions[from];
}

// Sharp-edge constraints of adjacent faces that disagree by more than this after transport across
// their edge (modulo a quarter turn) force a singularity between them. Along a feature line and at
// a right-angled feature corner they agree; on a scan, where tessellation noise makes many edges
// sharp (a fifth of dragon's at 35 degrees), they do not.
constexpr double kConflictingConstraint = std::numbers::pi / 6;

// The rank of a face's constraint: a boundary edge's outranks every sharp edge (ranked by their
// dihedral angles).
constexpr double kBoundaryRank = 2 * std::numbers::pi;

// Frees the faces whose sharp-edge constraint conflicts with a neighbour's (boundary constraints
// stay): the smoothest field decides there instead of the noise.
void free_conflicting_constraints(const Connectivity& c, const std::vector<double>& kappa,
                                  const std::vector<double>& rank, FaceConstraints& constraints) {
  std::vector<std::uint8_t> conflict(constraints.fixed.size(), 0);
  for (Index h = 0; h < c.corner_count; ++h) {
    if (c.is_boundary_halfedge(c.twin[h])) continue;
    const Index f = c.face[h];
    const Index g = c.face[c.twin[h]];
    if (!constraints.fixed[f] || !constraints.fixed[g]) continue;
    const double turn = std::remainder(constraints.angle[f] + kappa[h] - constraints.angle[g],
                                       std::numbers::pi / 2);
    if (std::abs(turn) > kConflictingConstraint) conflict[f] = conflict[g] = 1;
  }
  for (Index f = 0; f < conflict.size(); ++f)
    if (conflict[f] && rank[f] < kBoundaryRank) constraints.fixed[f] = 0;
}

}  // namespace

FaceConstraints feature_constraints(const Mesh& mesh, const Connectivity& c,
                                    const FaceFrames& frames, const std::vector<double>& kappa,
                                    double sharp_radians) {
  const std::vector<double> dihedral = dihedral_angles(mesh, c);
  const std::vector<std::uint8_t> sharp = feature_edges(c, dihedral, sharp_radians);
  const BoundaryTangents boundary = boundary_tangents(mesh, c);
  FaceConstraints constraints;
  constraints.fixed.assign(mesh.face_count(), 0);
  constraints.angle.assign(mesh.face_count(), 0.0);
  // Boundary edges rank above every sharp edge.
  std::vector<double> rank(mesh.face_count(), 0.0);
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index e = c.edge[h];
    if (!c.is_boundary_edge(e) && !sharp[e]) continue;
    const double r = c.is_boundary_edge(e) ? kBoundaryRank : std::abs(dihedral[e]);
    const Index f = c.face[h];
    if (constraints.fixed[f] && r <= rank[f]) continue;
    constraints.fixed[f] = 1;
    rank[f] = r;
    constraints.angle[f] = frames.angle(
        f, c.is_boundary_edge(e) ? boundary.edge_tangent[e] : feature_tangent(mesh, c, sharp, h));
  }
  free_conflicting_constraints(c, kappa, rank, constraints);
  for (std::uint8_t fixed : constraints.fixed) constraints.count += fixed;
  return constraints;
}

std::vector<std::complex<double>> curvature_targets(const Mesh& mesh, const FaceFrames& frames) {
  const std::vector<Eigen::Vector3d> normals = vertex_normals(mesh);
  std::vector<std::complex<double>> target(mesh.face_count());
  double magnitude_sum = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d s = shape_operator(mesh, frames, normals, f);
    // (a - c)/2 + i b = (k1 - k2)/2 exp(2 i phi); its square turns the principal direction pair
    // into one value of the power representation.
    const std::complex<double> half_anisotropy(0.5 * (s[0] - s[2]), s[1]);
    target[f] = half_anisotropy * half_anisotropy;
    magnitude_sum += std::abs(target[f]);
  }
  const double mean = magnitude_sum / std::max<std::size_t>(1, mesh.face_count());
  if (!(mean > 0)) return target;
  for (std::complex<double>& t : target) {
    t /= mean;
    if (std::abs(t) > 1) t /= std::abs(t);
  }
  return target;
}

}  // namespace tessera
