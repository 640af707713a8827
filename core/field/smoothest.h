// The smoothest cross field of a component without constraints (SPEC "Cross field"): the
// eigenvector of the smallest eigenvalue of the connection Laplacian in the power representation,
// L z = lambda M z (design.h), found by block inverse iteration with Rayleigh-Ritz (a few vectors
// at once: the lowest eigenvalues of smooth surfaces lie close together, where single-vector
// inverse iteration crawls).
//
// Symmetric surfaces have a degenerate lowest eigenspace (a torus of revolution: modes turning
// k and -k times around it). Every vector of it is equally smooth, but mixtures vanish somewhere
// (spurious singularity pairs) while pure modes do not. So within the lowest eigenspace the field
// with the most uniform magnitude is taken (least sum_T M_T |z_T|^4 at unit mass norm).
//
// In:  the factorized matrix A = L + shift M (SPD) and A itself, the diagonal of M per row, the
//      first rows of the faces of each component (two rows per face: real and imaginary part).
// Out: per component a vector of unit mass norm on its rows, zero elsewhere, turned so that
//      sum_k (k + 1) M_k z_k over its faces is real and positive (every rotation of the field is
//      as smooth: the rule, not rounding, picks one); deterministic.
// Throws CancelledError when cancelled.
#pragma once

#include <vector>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "base/progress.h"
#include "mesh/mesh.h"

namespace tessera {

Eigen::VectorXd smoothest_power_fields(
    const Eigen::SparseMatrix<double>& matrix,
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& solver, const Eigen::VectorXd& mass,
    const std::vector<std::vector<Index>>& component_rows, const Progress& progress);

}  // namespace tessera
