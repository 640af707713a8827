// The distance between the quad mesh and its input surface (issue 39 "CLI": Hausdorff distance
// relative to the bounding box), approximated by samples: the vertices and face centroids of each
// mesh against the other's triangles (polygons fanned), the largest distance found in either
// direction.
//
// In:  two meshes. Out: that distance over the bounding-box diagonal of `a`.
#pragma once

#include "mesh/mesh.h"

namespace tessera::remesh {

double relative_hausdorff(const Mesh& a, const Mesh& b);

}  // namespace tessera::remesh
