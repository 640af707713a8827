#include "field/face_frames.h"

#include <cmath>
#include <numbers>
#include <string>

#include "base/error.h"
#include "mesh/describe.h"
#include "mesh/geometry.h"

namespace tessera {

double FaceFrames::angle(Index f, const Eigen::Vector3d& x) const {
  return std::atan2(x.dot(e2[f]), x.dot(e1[f]));
}

Eigen::Vector3d FaceFrames::direction(Index f, double a) const {
  return std::cos(a) * e1[f] + std::sin(a) * e2[f];
}

FaceFrames face_frames(const Mesh& mesh) {
  FaceFrames frames;
  const std::size_t n = mesh.face_count();
  frames.e1.resize(n);
  frames.e2.resize(n);
  frames.normal.resize(n);
  frames.area.resize(n);
  for (Index f = 0; f < n; ++f) {
    if (mesh.face_size(f) != 3)
      throw TopologyError(describe_face(mesh, f) +
                          " is not a triangle; cross fields need a triangle mesh (triangulate it)");
    const auto v = mesh.face(f);
    const Eigen::Vector3d first = mesh.positions[v[1]] - mesh.positions[v[0]];
    const Eigen::Vector3d vector_area = face_vector_area(mesh, f);
    const double longest =
        std::max({first.squaredNorm(), (mesh.positions[v[2]] - mesh.positions[v[1]]).squaredNorm(),
                  (mesh.positions[v[0]] - mesh.positions[v[2]]).squaredNorm()});
    // Relative to the longest edge, so that the test does not depend on the mesh's scale.
    if (!(vector_area.norm() > 1e-14 * longest))
      throw GeometryError(describe_face(mesh, f) +
                          " has no area (degenerate triangle), so no tangent plane for the field; "
                          "remove or repair degenerate faces first");
    frames.area[f] = vector_area.norm();
    frames.normal[f] = vector_area.normalized();
    frames.e1[f] = first.normalized();
    frames.e2[f] = frames.normal[f].cross(frames.e1[f]);
  }
  return frames;
}

Eigen::Vector3d halfedge_vector(const Mesh& mesh, const Connectivity& c, Index h) {
  return mesh.positions[c.to_vertex[h]] - mesh.positions[c.from_vertex(h)];
}

std::vector<double> connection_angles(const Mesh& mesh, const Connectivity& c,
                                      const FaceFrames& frames) {
  std::vector<double> kappa(c.halfedge_count(), 0.0);
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (c.is_boundary_edge(e)) continue;
    const Index h = c.edge_halfedge[e];
    const Index t = c.twin[h];
    // The shared edge is the one direction both faces see; unfolding keeps its angle to any
    // tangent direction, so the frames differ by the difference of its two angles.
    const Eigen::Vector3d d = halfedge_vector(mesh, c, h);
    kappa[h] = wrap_angle(frames.angle(c.face[t], d) - frames.angle(c.face[h], d));
    kappa[t] = wrap_angle(-kappa[h]);
  }
  return kappa;
}

double wrap_angle(double a) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  a = std::remainder(a, kTwoPi);  // in [-pi, pi]
  return a == -std::numbers::pi ? std::numbers::pi : a;
}

}  // namespace tessera
