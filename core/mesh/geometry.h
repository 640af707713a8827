// Geometric quantities of a mesh: face normals and areas, edge dihedral angles, bounding box.
//
// In:  a mesh with indices in range (polygons allowed; a polygon's normal and area are those of
//      its vector area, exact for planar polygons).
// Out: plain values per face / per edge / per vertex; nothing throws.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/connectivity.h"
#include "mesh/mesh.h"

namespace tessera {

// Half the sum of the corner cross products: normal direction times area.
Eigen::Vector3d face_vector_area(const Mesh& mesh, Index f);
double face_area(const Mesh& mesh, Index f);
// Unit normal (right-hand rule over the corners); zero for a face without area.
Eigen::Vector3d face_normal(const Mesh& mesh, Index f);

std::vector<double> face_areas(const Mesh& mesh);
std::vector<Eigen::Vector3d> face_normals(const Mesh& mesh);
// Area-weighted average of the incident face normals, normalized; zero where that sum vanishes.
std::vector<Eigen::Vector3d> vertex_normals(const Mesh& mesh);

// The interior angle of the triangle at the start of corner halfedge h, in [0, pi].
double corner_angle(const Mesh& mesh, const Connectivity& connectivity, Index h);

// Per edge, the signed angle between the normals of its two faces, in [-pi, pi]: 0 where flat,
// positive where the surface bends away from its normals (convex), 0 on boundary edges.
std::vector<double> dihedral_angles(const Mesh& mesh, const Connectivity& connectivity);

struct BoundingBox {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  double diagonal() const { return (max - min).norm(); }
};

// The box of all vertex positions (zero box for a mesh without vertices).
BoundingBox bounding_box(const Mesh& mesh);

}  // namespace tessera
