// Per-triangle tangent frames and the discrete connection between them (Sec. 6.3, Def. 6.7).
// Tangent directions are stored as angles in each triangle's own frame; crossing an interior edge
// from face f to face g changes the angle by the edge's connection angle kappa (the rotation
// between the two frames once g is unfolded into the plane of f).
//
// In:  a triangle mesh (and its connectivity for the connection).
// Out: per face an orthonormal frame: e1 along the face's first halfedge, normal n (right-hand
//      rule), e2 = n x e1. Per halfedge h (face f, twin in face g) the angle kappa_h in (-pi, pi]
//      that carries a direction at angle a in f's frame to angle a + kappa_h in g's frame;
//      kappa_twin(h) = -kappa_h; 0 on boundary edges.
// Throws TopologyError for a face that is not a triangle, GeometryError for a face without area.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "mesh/connectivity.h"
#include "mesh/mesh.h"

namespace tessera {

struct FaceFrames {
  std::vector<Eigen::Vector3d> e1;      // per face, unit, along the first halfedge
  std::vector<Eigen::Vector3d> e2;      // per face, unit, n x e1
  std::vector<Eigen::Vector3d> normal;  // per face, unit
  std::vector<double> area;             // per face

  // Coordinates of a 3D vector in the frame of face f (its normal part dropped).
  Eigen::Vector2d local(Index f, const Eigen::Vector3d& x) const {
    return {x.dot(e1[f]), x.dot(e2[f])};
  }
  Eigen::Vector3d global(Index f, const Eigen::Vector2d& x) const {
    return x.x() * e1[f] + x.y() * e2[f];
  }
  // Angle of a 3D tangent vector in the frame of face f.
  double angle(Index f, const Eigen::Vector3d& x) const;
  // The unit tangent vector at an angle in the frame of face f.
  Eigen::Vector3d direction(Index f, double angle) const;
};

FaceFrames face_frames(const Mesh& mesh);

// The vector of halfedge h, from its start to its end vertex.
Eigen::Vector3d halfedge_vector(const Mesh& mesh, const Connectivity& connectivity, Index h);

std::vector<double> connection_angles(const Mesh& mesh, const Connectivity& connectivity,
                                      const FaceFrames& frames);

// The angle reduced to (-pi, pi].
double wrap_angle(double a);

}  // namespace tessera
