#include "remesh/quad_quality.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "base/error.h"
#include "mesh/connectivity.h"

namespace tessera::remesh {
namespace {

using Eigen::Vector3d;

// Newell's normal of a polygon (not normalized).
Vector3d polygon_normal(const Mesh& mesh, std::size_t f) {
  const auto v = mesh.face(f);
  Vector3d n = Vector3d::Zero();
  for (std::size_t k = 0; k < v.size(); ++k)
    n += mesh.positions[v[k]].cross(mesh.positions[v[(k + 1) % v.size()]]);
  return n;
}

double corner_jacobian(const Mesh& mesh, std::size_t f, std::size_t k, const Vector3d& own) {
  const auto v = mesh.face(f);
  const Vector3d& x = mesh.positions[v[k]];
  const Vector3d e1 = mesh.positions[v[(k + 1) % v.size()]] - x;
  const Vector3d e2 = mesh.positions[v[(k + v.size() - 1) % v.size()]] - x;
  const double lengths = e1.norm() * e2.norm();
  return lengths > 0 ? e1.cross(e2).dot(own) / lengths : 0.0;
}

void corner_figures(const Mesh& mesh, const std::vector<Vector3d>& normal, QuadQuality& q) {
  q.min_scaled_jacobian = 1;
  double jacobian_sum = 0, deviation_sum = 0;
  std::size_t corners = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto v = mesh.face(f);
    Vector3d reference = Vector3d::Zero();
    for (Index i : v) reference += normal[i];
    const Vector3d own = polygon_normal(mesh, f).normalized();
    if (own.dot(reference) <= 0) ++q.flipped_quads;
    double least = 1;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const Vector3d& x = mesh.positions[v[k]];
      const Vector3d e1 = mesh.positions[v[(k + 1) % v.size()]] - x;
      const Vector3d e2 = mesh.positions[v[(k + v.size() - 1) % v.size()]] - x;
      const double lengths = e1.norm() * e2.norm();
      const double jacobian = corner_jacobian(mesh, f, k, own);
      least = std::min(least, jacobian);
      if (jacobian <= 0) q.nonpositive_corners.push_back(v[k]);
      const double angle =
          lengths > 0 ? std::acos(std::clamp(e1.dot(e2) / lengths, -1.0, 1.0)) : 0.0;
      const double deviation = std::abs(angle * 180 / M_PI - 90);
      q.max_angle_deviation = std::max(q.max_angle_deviation, deviation);
      deviation_sum += deviation;
      ++corners;
    }
    if (least <= 0) ++q.nonpositive_jacobian_quads;
    q.min_scaled_jacobian = std::min(q.min_scaled_jacobian, least);
    jacobian_sum += least;
  }
  q.mean_scaled_jacobian = mesh.face_count() ? jacobian_sum / double(mesh.face_count()) : 0;
  q.mean_angle_deviation = corners ? deviation_sum / double(corners) : 0;
}

void topology_figures(const Mesh& mesh, QuadQuality& q) {
  Connectivity c;
  try {
    c = build_connectivity(mesh);
  } catch (const Error& error) {
    q.problem = error.what();
    return;
  }
  q.manifold = true;
  q.boundary_edges = c.halfedge_count() - c.corner_count;
  q.euler_characteristic =
      long(mesh.vertex_count()) - long(c.edge_count()) + long(mesh.face_count());
  for (Index v = 0; v < c.vertex_count(); ++v) {
    if (c.vertex_halfedge[v] == kNoIndex) continue;
    const std::size_t valence = outgoing_halfedges(c, v).size();
    if (valence != (c.is_boundary_vertex(v) ? 3u : 4u)) q.irregular.push_back(v);
  }
  q.irregular_vertices = q.irregular.size();
}

}  // namespace

double least_scaled_jacobian(const Mesh& mesh, std::size_t f, const std::vector<Vector3d>& normal) {
  Vector3d reference = Vector3d::Zero();
  for (Index i : mesh.face(f)) reference += normal[i];
  const Vector3d own = polygon_normal(mesh, f).normalized();
  if (!(own.dot(reference) > 0)) return -1;
  double least = 1;
  for (std::size_t k = 0; k < mesh.face_size(f); ++k)
    least = std::min(least, corner_jacobian(mesh, f, k, own));
  return least;
}

QuadQuality quad_quality(const Mesh& quads, const std::vector<Vector3d>& surface_normal) {
  QuadQuality q;
  topology_figures(quads, q);
  corner_figures(quads, surface_normal, q);
  return q;
}

}  // namespace tessera::remesh
