// The cross field of a triangle mesh as a value (Sec. 6.3, Def. 6.7): per face the angle of one
// representative direction u_T of the cross (v_T = n x u_T is the next one counterclockwise), per
// edge the connection angle kappa_ij and the period jump p_ij, per vertex the index, and the
// singularities.
//
// Conventions (fixed here, used by every later stage):
//  - Period jump (6.6): p_ij in Z4 is the quarter turn that maps chart coordinates of face i to
//    those of face j, e|T_j = J^p_ij e|T_i, where a face's chart measures a tangent vector x as
//    (<x, u_T>, <x, v_T>). The field angles then satisfy
//    theta_j = theta_i + kappa_ij - p_ij * pi/2 + delta_ij with |delta_ij| <= pi/4 (principal
//    matching picks the p_ij with the smallest |delta_ij|), except on the few edges where a
//    vertex of index 1/2 or more was split (field_topology.h, split_merged_singularities());
//    p_ji = -p_ij mod 4.
//  - Index of an interior vertex: (angle defect + sum of delta around it ccw) / 2pi, a multiple of
//    1/4; valence = 4 - 4 * index (index 1/4: valence 3, index -1/4: valence 5), the number of
//    ports (Def. 2.3, 2.4).
//  - Index of a boundary vertex: the field is read relative to the boundary, as a boundary-aligned
//    field requires: (pi - interior angle + sum of delta + the turn that aligns the field to the
//    first boundary edge - the turn at the last one) / 2pi, also a multiple of 1/4 (for a field
//    aligned to the boundary: 1/4 at a 90 degree corner, -1/4 at a 270 degree corner);
//    valence = 2 - 4 * index (a straight boundary vertex has two half-ports).
//  - Poincare-Hopf: the indices of all vertices sum to the Euler characteristic V - E + F.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "field/face_frames.h"
#include "mesh/connectivity.h"
#include "mesh/mesh.h"

namespace tessera {

struct Singularity {
  Index vertex = 0;
  double index = 0;  // a multiple of 1/4
  int valence = 4;
};

struct CrossField {
  std::vector<double> angle;               // per face, theta_T of u_T in the face frame
  std::vector<Eigen::Vector3d> direction;  // per face, u_T as a unit 3D vector
  std::vector<double> kappa;               // per halfedge, the connection angle (face_frames.h)
  std::vector<std::uint8_t> period_jump;   // per halfedge, p in {0, 1, 2, 3}; 0 on the boundary
  std::vector<int> vertex_index;           // per vertex, 4 * index (an integer)
  std::vector<Singularity> singularities;  // vertices with nonzero index, by vertex number
  long euler_characteristic = 0;           // V - E + F of the mesh
  double index_sum = 0;                    // sum of all vertex indices (Poincare-Hopf: == chi)
};

// The cross field with the given per-face angles: connection, principal matching, indices, merged
// singularities split, singularities (field_topology.h). `angle` has one entry per face.
CrossField cross_field_from_angles(const Mesh& mesh, const Connectivity& connectivity,
                                   const FaceFrames& frames, std::vector<double> angle);

// The same with u_T given as 3D vectors per face (projected to the face plane).
// Throws InputError if the count differs from the face count or a vector is (nearly) normal to its
// face.
CrossField cross_field_from_directions(const Mesh& mesh, const Connectivity& connectivity,
                                       const FaceFrames& frames,
                                       const std::vector<Eigen::Vector3d>& directions);

}  // namespace tessera
