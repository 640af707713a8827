// A smooth cross field by a global linear method in the power representation z_T = exp(4 i theta_T)
// (the cross field that Sec. 6.3-6.6 take as input; SPEC "Cross field"). Smoothness is the
// connection Dirichlet energy sum_ij w_ij |z_j - exp(4 i kappa_ij) z_i|^2 over interior edges
// (w_ij = |e_ij| / distance of the face barycentres across e_ij), which is the smoothness energy of
// Def. 6.7 with the period jumps absorbed by the fourth power.
//  - Faces on boundary and sharp edges are hard constraints (alignment.h); the other faces come
//    from one sparse linear solve.
//  - align == curvature adds curvature_weight * sum_T (A_T / total area) |z_T - c_T|^2 towards the
//    principal curvature target c_T (alignment.h); the blend is one linear solve as well. Both
//    terms are dimensionless, so the weight means the same at any scale and resolution.
//  - A connected component with neither constraints nor curvature term gets its smoothest field:
//    the eigenvector of the smallest eigenvalue (smoothest.h), with the same sparse LDLT
//    factorization.
//
// In:  a triangle mesh with connectivity and face frames, the options, a progress listener.
// Out: the CrossField (cross_field.h), deterministic for a given mesh and options.
// Throws InputError for bad options, CancelledError when cancelled.
#pragma once

#include "base/progress.h"
#include "field/cross_field.h"

namespace tessera {

enum class FieldAlignment { smooth, curvature };

struct FieldOptions {
  FieldAlignment align = FieldAlignment::smooth;
  double curvature_weight = 10;  // blend weight of the curvature target (align == curvature)
  double sharp_degrees = 35;     // edges with a larger dihedral angle are hard constraints
};

CrossField design_cross_field(const Mesh& mesh, const Connectivity& connectivity,
                              const FaceFrames& frames, const FieldOptions& options,
                              const Progress& progress);

}  // namespace tessera
