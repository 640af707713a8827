// The checks and quality figures of a quad mesh extracted from a layout (issue 39 "Output"):
// manifold, closed, Euler characteristic, quads whose normal opposes the surface under them
// (flipped: the quad's own normal, Newell's, against the sum of the input's normals at its
// corners), the scaled Jacobian (per corner, cross(e1, e2) . N / (|e1| |e2|) with N the quad's own
// unit normal, as for planar quads; per quad the least of its four corners; <= 0 at a reflex or
// folded corner), the corner angles' deviation
// from 90 degrees, and the irregular vertices (valence other than 4 inside, 3 on the boundary).
//
// In:  an all-quad mesh, the input surface's normal at each of its vertices.
// Out: the figures; a mesh that is not a manifold says so in `manifold` (nothing throws).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace tessera::remesh {

struct QuadQuality {
  bool manifold = false;
  std::size_t boundary_edges = 0;
  long euler_characteristic = 0;
  std::size_t flipped_quads = 0;
  std::size_t nonpositive_jacobian_quads = 0;
  double min_scaled_jacobian = 0;
  double mean_scaled_jacobian = 0;
  double max_angle_deviation = 0;  // degrees
  double mean_angle_deviation = 0;
  std::size_t irregular_vertices = 0;
  std::vector<Index> irregular;            // the irregular vertices
  std::vector<Index> nonpositive_corners;  // the vertices of the quad corners with a Jacobian <= 0
  std::string problem;                     // why the mesh is not a manifold, if it is not
};

// The least scaled Jacobian over the corners of face f, and -1 if the face is flipped.
double least_scaled_jacobian(const Mesh& mesh, std::size_t f,
                             const std::vector<Eigen::Vector3d>& surface_normal);

QuadQuality quad_quality(const Mesh& quads, const std::vector<Eigen::Vector3d>& surface_normal);

}  // namespace tessera::remesh
