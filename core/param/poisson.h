// The Poisson energy of a parameterization against a combed cross field (Sec. 6.6, (6.5);
// App. A, (A.1)-(A.5)):
//   E_f = sum_T A_T (|h grad u - u_T|^2 + |h grad v - v_T|^2)
// with (u, v) linear on each triangle, one value per wedge (wedges.h), and u_T, v_T = J u_T the
// combed field's unit frame. grad of the hat function of corner i is J e_i / (2 A_T), e_i the edge
// opposite the corner (App. A).
//
// The system is assembled for E_f / h^2 = sum_T A_T |grad x - target_T|^2 per coordinate, whose
// matrix is the cotangent Laplacian (entries of order 1 whatever the mesh's scale) and whose
// solution is in parameter units (one unit = h on the surface).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include "field/cross_field.h"
#include "param/wedges.h"

namespace tessera {

struct PoissonProblem {
  std::vector<std::array<Eigen::Vector2d, 3>> gradient;  // per face, of its corners' hat functions,
                                                         // in the face frame
  std::vector<Eigen::Vector2d> frame_u;     // per face, u_T in the face frame (unit); v_T = J u_T
  std::vector<double> area;                 // per face
  std::vector<std::array<Index, 3>> wedge;  // per face, the wedges of its corners
  std::size_t wedge_count = 0;
  double h = 1;  // sizing: parameter unit length on the surface
};

// Variables are ordered (u, v) per wedge: variable 2w + 0 is u of wedge w, 2w + 1 its v.
PoissonProblem poisson_problem(const Mesh& mesh, const FaceFrames& frames, const CrossField& combed,
                               const Wedges& wedges, double h);

// The 2W x 2W matrix Q and right-hand side b of E_f / h^2 = x^T Q x - 2 b^T x + const.
Eigen::SparseMatrix<double> poisson_matrix(const PoissonProblem& problem);
Eigen::VectorXd poisson_rhs(const PoissonProblem& problem);

// E_f of (6.5) for wedge values x (2W entries).
double poisson_energy(const PoissonProblem& problem, const Eigen::VectorXd& x);

// J^r applied to a 2D vector (J: rotation by +90 degrees).
Eigen::Vector2d quarter_turns(const Eigen::Vector2d& x, int r);

}  // namespace tessera
