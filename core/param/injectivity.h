// Injectivity by bisector constraints (Sec. 6.5, (6.2), (6.3); App. A, (A.6)). In a constrained
// triangle the gradients of the parameterization stay within 45 degrees of the field's frame,
//   <h grad u, u_T + v_T> >= m,  <h grad u, u_T - v_T> >= m,
//   <h grad v, u_T + v_T> >= m,  <h grad v, v_T - u_T> >= m,
// with a margin m > 0 for the strict inequalities; then (grad u, grad v) keeps the frame's
// orientation and the triangle is not flipped. The thesis constrains the triangles around the
// singularities; here those that break the constraints and every flipped triangle are
// constrained (the others already satisfy them and are left alone); later rounds retry the
// triangles still flipped, the last ones only those away from the singularities' one-rings. A
// round frees
// the unknowns that move a triangle within a few vertex rings of the constrained triangles (the
// ring count grows by one per round, and for two rounds so does the number of triangles an
// unknown may move: wedges first, then translations of short cut arcs), holds everything else,
// and solves with
// GLPK the linear program
//   minimize  sum_T (A_T / mean area) |h grad(u, v) - (u_T, v_T)|_1  +  W sum slack
// subject to the bisector constraints, each with a slack (so the program is always feasible), on
// every triangle those unknowns touch. Unknowns that share no triangle form separate programs.
//
// In:  the Poisson problem, the seam basis P (x = P y), per-face "around a singularity" flags, the
//      reduced unknowns y of the unconstrained solve (updated in place).
// Out: a report of the work done. Throws CancelledError when cancelled.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include "base/progress.h"
#include "param/poisson.h"

namespace tessera {

struct InjectivityOptions {
  int rounds = 5;
  int ring_rounds = 3;          // rounds that also retry flipped triangles around singularities
  double margin = 0.1;          // m, relative to the unit frame
  double slack_weight = 100.0;  // W
  // Larger programs are skipped (their triangles keep their values): widespread flips mean the
  // field does not suit the surface, and the simplex method would take minutes.
  std::size_t max_program_faces = 5000;
  // An unknown moving more triangles than this (times 4 per round, up to 16 times) is held: the
  // first round moves wedges only, later ones also the translations of short cut arcs, never
  // those of long arcs.
  std::size_t column_faces = 16;
};

struct InjectivityReport {
  std::size_t rounds = 0;             // rounds that had triangles to constrain
  std::size_t programs = 0;           // linear programs set up
  std::size_t unsolved_programs = 0;  // of those, where GLPK found no optimum (values kept)
  std::size_t skipped_programs = 0;   // above max_program_faces, not solved
  std::size_t constrained_faces = 0;  // triangles under bisector constraints, summed over rounds
};

// Per face 1 if its uv triangle is flipped or degenerate (non-positive signed area).
std::vector<std::uint8_t> flipped_faces(const PoissonProblem& problem, const Eigen::VectorXd& x);

InjectivityReport enforce_bisector_constraints(const Mesh& mesh, const PoissonProblem& problem,
                                               const Eigen::SparseMatrix<double>& basis,
                                               const std::vector<std::uint8_t>& singular_ring,
                                               const InjectivityOptions& options,
                                               Eigen::VectorXd& y, const Progress& progress);

}  // namespace tessera
