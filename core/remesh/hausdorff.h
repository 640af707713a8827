// The distance between the quad mesh and its input surface (issue 39 "CLI": Hausdorff distance
// relative to the bounding box), approximated by samples: the vertices and face centroids of each
// mesh against the other's triangles (polygons fanned), the largest distance found in either
// direction.
//
// In:  two meshes. Out: that distance over the bounding-box diagonal of `a`.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "mesh/triangle_grid.h"

namespace tessera::remesh {

double relative_hausdorff(const Mesh& a, const Mesh& b);

// relative_hausdorff(a, b) for many b of one a (the quad meshes of one input at several sizes):
// a's samples, grid and diagonal are made once. `a` must outlive it (and stay where it is).
class HausdorffReference {
 public:
  explicit HausdorffReference(const Mesh& a);
  double relative_to(const Mesh& b) const;

 private:
  const Mesh* a_;
  TriangleGrid grid_;
  std::vector<Eigen::Vector3d> samples_;
  double diagonal_ = 0;
};

}  // namespace tessera::remesh
