// Self-intersections of a surface mesh: pairs of triangles (polygons fanned as in triangulate())
// that intersect although they share no vertex. Pairs that share a vertex touch there by
// construction and are not tested, so a fold between neighbouring faces goes unnoticed; every
// crossing of separate sheets is found.
//
// In:  a mesh with indices in range.
// Out: the number of intersecting triangle pairs and the faces involved. Candidate pairs come from
// a
//      uniform grid over the triangles' bounding boxes (cell size about the mean triangle extent),
//      each pair tested once; the test is exact in its signs up to floating point (Moeller's
//      interval overlap, a 2D test for coplanar pairs).
// Throws CancelledError through `progress`.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "base/progress.h"
#include "mesh/mesh.h"

namespace tessera {

struct SelfIntersections {
  std::size_t triangle_pairs = 0;
  std::vector<Index> faces;  // the mesh faces with at least one intersecting triangle, ascending
};

SelfIntersections find_self_intersections(const Mesh& mesh, const Progress& progress = Progress());

// Whether the closed triangles abc and def have a point in common.
bool triangles_intersect(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& d,
                         const Eigen::Vector3d& e, const Eigen::Vector3d& f);

}  // namespace tessera
