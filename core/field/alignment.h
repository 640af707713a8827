// What a designed cross field aligns to (Sec. 6.3 input field; SPEC "Cross field"):
//  - hard constraints: every face on a boundary edge or a sharp edge (dihedral angle above a
//    threshold) has its cross along that edge's curve (the boundary's, mesh/boundary_tangents.h,
//    or the feature line's); a face with several such edges takes the boundary
//    edge, else the sharpest one; two adjacent faces whose sharp-edge constraints disagree by more
//    than 30 degrees (modulo a quarter turn) are both left free, as noise of a scan;
//  - a soft target: the principal curvature directions, in the power representation z^4 (so both
//    principal directions give the same value), weighted by how anisotropic the curvature is.
//
// In:  a triangle mesh, its connectivity and face frames.
// Out: per-face values; nothing throws.
#pragma once

#include <complex>
#include <cstdint>
#include <vector>

#include "field/face_frames.h"

namespace tessera {

struct FaceConstraints {
  std::vector<std::uint8_t> fixed;  // per face: 1 if the cross is prescribed
  std::vector<double> angle;        // per face: the prescribed angle in the face frame
  std::size_t count = 0;            // faces with fixed == 1
};

// Faces on boundary edges and on edges whose |dihedral angle| exceeds sharp_radians; `kappa` is
// the connection (face_frames.h), used to compare the constraints of neighbouring faces.
FaceConstraints feature_constraints(const Mesh& mesh, const Connectivity& connectivity,
                                    const FaceFrames& frames, const std::vector<double>& kappa,
                                    double sharp_radians);

// Per face ((k1 - k2) / 2)^2 exp(4 i phi) of the shape operator (k1 >= k2 along phi), estimated
// from the change of the vertex normals along the edges, divided by its mean magnitude over the
// mesh and clamped to magnitude 1, so that the blend weight does not depend on the mesh's size.
std::vector<std::complex<double>> curvature_targets(const Mesh& mesh, const FaceFrames& frames);

}  // namespace tessera
