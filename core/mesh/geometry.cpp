#include "mesh/geometry.h"

#include <cmath>

#include <Eigen/Geometry>

namespace tessera {

Eigen::Vector3d face_vector_area(const Mesh& mesh, Index f) {
  // Relative to the first corner, so that far-from-origin faces keep their precision.
  const auto face = mesh.face(f);
  const Eigen::Vector3d& origin = mesh.positions[face[0]];
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i + 1 < face.size(); ++i)
    sum += (mesh.positions[face[i]] - origin).cross(mesh.positions[face[i + 1]] - origin);
  return 0.5 * sum;
}

double face_area(const Mesh& mesh, Index f) {
  return face_vector_area(mesh, f).norm();
}

Eigen::Vector3d face_normal(const Mesh& mesh, Index f) {
  const Eigen::Vector3d a = face_vector_area(mesh, f);
  const double n = a.norm();
  return n > 0 ? Eigen::Vector3d(a / n) : Eigen::Vector3d::Zero();
}

std::vector<double> face_areas(const Mesh& mesh) {
  std::vector<double> areas(mesh.face_count());
  for (Index f = 0; f < mesh.face_count(); ++f) areas[f] = face_area(mesh, f);
  return areas;
}

std::vector<Eigen::Vector3d> face_normals(const Mesh& mesh) {
  std::vector<Eigen::Vector3d> normals(mesh.face_count());
  for (Index f = 0; f < mesh.face_count(); ++f) normals[f] = face_normal(mesh, f);
  return normals;
}

std::vector<Eigen::Vector3d> vertex_normals(const Mesh& mesh) {
  std::vector<Eigen::Vector3d> normals(mesh.vertex_count(), Eigen::Vector3d::Zero());
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = face_vector_area(mesh, f);
    for (Index v : mesh.face(f)) normals[v] += a;
  }
  for (Eigen::Vector3d& n : normals) {
    const double length = n.norm();
    n = length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
  }
  return normals;
}

double corner_angle(const Mesh& mesh, const Connectivity& c, Index h) {
  const Eigen::Vector3d& at = mesh.positions[c.from_vertex(h)];
  const Eigen::Vector3d a = mesh.positions[c.to_vertex[h]] - at;
  const Eigen::Vector3d b = mesh.positions[c.from_vertex(c.prev[h])] - at;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

std::vector<double> dihedral_angles(const Mesh& mesh, const Connectivity& c) {
  const std::vector<Eigen::Vector3d> normals = face_normals(mesh);
  std::vector<double> angles(c.edge_count(), 0.0);
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (c.is_boundary_edge(e)) continue;
    const Index h = c.edge_halfedge[e];
    const Eigen::Vector3d& n1 = normals[c.face[h]];
    const Eigen::Vector3d& n2 = normals[c.face[c.twin[h]]];
    const Eigen::Vector3d along =
        (mesh.positions[c.to_vertex[h]] - mesh.positions[c.from_vertex(h)]).normalized();
    // atan2 of sine and cosine is accurate near 0 and pi, unlike acos of the dot product.
    angles[e] = std::atan2(n1.cross(n2).dot(along), n1.dot(n2));
  }
  return angles;
}

BoundingBox bounding_box(const Mesh& mesh) {
  BoundingBox box;
  if (mesh.positions.empty()) return box;
  box.min = box.max = mesh.positions.front();
  for (const Eigen::Vector3d& p : mesh.positions) {
    box.min = box.min.cwiseMin(p);
    box.max = box.max.cwiseMax(p);
  }
  return box;
}

}  // namespace tessera
