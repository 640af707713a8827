#include "field/smoothest.h"

#include <cmath>
#include <complex>
#include <random>

#include <Eigen/Dense>

namespace tessera {
namespace {

using Dense = Eigen::MatrixXd;

constexpr int kBlock = 8;  // real vectors: four complex directions
constexpr int kMaxIterations = 200;
constexpr double kResidual = 1e-6;    // relative residual of the lowest Ritz pair
constexpr double kDegenerate = 1e-6;  // relative gap below which eigenvalues count as equal
constexpr int kUniformIterations = 50;

struct RitzPairs {
  Dense vectors;           // columns, mass-orthonormal
  Eigen::VectorXd values;  // ascending
};

// Rayleigh-Ritz of the matrix in the span of the columns of x.
RitzPairs rayleigh_ritz(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& mass,
                        const Dense& x) {
  const Dense k = x.transpose() * (a * x);
  const Dense g = x.transpose() * mass.asDiagonal() * x;
  Eigen::GeneralizedSelfAdjointEigenSolver<Dense> small(0.5 * (k + k.transpose()),
                                                        0.5 * (g + g.transpose()));
  return {x * small.eigenvectors(), small.eigenvalues()};
}

// The combination c of the columns (mass-orthonormal) with |c| = 1 whose field has the least
// sum_T M_T |z_T|^4: repeatedly the lowest eigenvector of H(c) = sum_T M_T |z_T|^2 B_T^T B_T
// (B_T: the two rows of face T), the stationarity condition of that quartic on the unit sphere.
Eigen::VectorXd most_uniform(const Dense& basis, const Eigen::VectorXd& mass,
                             const std::vector<Index>& rows) {
  Dense b(2 * rows.size(), basis.cols());
  Eigen::VectorXd face_mass(2 * rows.size());
  for (Eigen::Index k = 0; k < static_cast<Eigen::Index>(rows.size()); ++k) {
    b.middleRows(2 * k, 2) = basis.middleRows(rows[k], 2);
    face_mass.segment<2>(2 * k).setConstant(mass[rows[k]]);
  }
  Eigen::VectorXd c = Eigen::VectorXd::Unit(basis.cols(), 0);
  for (int iteration = 0; iteration < kUniformIterations; ++iteration) {
    const Eigen::VectorXd z = b * c;
    Eigen::VectorXd weight(z.size());
    for (Eigen::Index k = 0; k < z.size(); k += 2)
      weight.segment<2>(k).setConstant(face_mass[k] * z.segment<2>(k).squaredNorm());
    const Dense h = b.transpose() * weight.asDiagonal() * b;
    Eigen::SelfAdjointEigenSolver<Dense> eigen(h);
    Eigen::VectorXd next = eigen.eigenvectors().col(0);
    if (next.dot(c) < 0) next = -next;
    const double change = (next - c).norm();
    c = next;
    if (change < 1e-12) break;
  }
  return basis * c;
}

// The smoothest field is defined up to a global rotation: with z every e^{i phi} z is an
// eigenvector of the same eigenvalue (the connection Laplacian is complex-linear), and which one
// the eigensolvers return is decided by rounding (the native and wasm builds returned z and -z for
// the icosphere: the same crosses turned by 45 degrees, another layout). The phase is fixed here:
// sum_k (k + 1) M_k z_k over the component's faces in their order is made real and positive (the
// face numbers break the surface's symmetries, so the sum does not vanish by symmetry).
Eigen::VectorXd with_fixed_phase(Eigen::VectorXd v, const Eigen::VectorXd& mass,
                                 const std::vector<Index>& rows) {
  std::complex<double> sum = 0;
  for (std::size_t k = 0; k < rows.size(); ++k)
    sum += static_cast<double>(k + 1) * mass[rows[k]] *
           std::complex<double>(v[rows[k]], v[rows[k] + 1]);
  if (std::abs(sum) == 0) return v;
  const std::complex<double> turn = std::conj(sum) / std::abs(sum);
  for (Index r : rows) {
    const std::complex<double> z = turn * std::complex<double>(v[r], v[r + 1]);
    v[r] = z.real();
    v[r + 1] = z.imag();
  }
  return v;
}

Eigen::VectorXd smoothest_on_component(
    const Eigen::SparseMatrix<double>& a,
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& solver, const Eigen::VectorXd& mass,
    const std::vector<Index>& rows, const Progress& progress) {
  const Eigen::Index n = mass.size();
  Eigen::VectorXd support = Eigen::VectorXd::Zero(n);
  for (Index r : rows) support.segment<2>(r).setOnes();
  const int block = static_cast<int>(std::min<std::size_t>(kBlock, 2 * rows.size()));
  Dense x = Dense::Zero(n, block);
  std::mt19937 random(12345);  // mt19937's sequence is fixed by the standard: same on every build
  for (int j = 0; j < block; ++j)
    for (Index r : rows)
      for (int i = 0; i < 2; ++i) x(r + i, j) = random() / 4294967296.0 - 0.5;

  RitzPairs ritz = rayleigh_ritz(a, mass, x);
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    progress.step("field", 0.3 + 0.6 * iteration / kMaxIterations);
    const Eigen::VectorXd lowest = ritz.vectors.col(0);
    const double residual = (a * lowest - ritz.values[0] * mass.cwiseProduct(lowest)).norm() /
                            (std::abs(ritz.values[0]) * mass.cwiseProduct(lowest).norm());
    if (residual < kResidual) break;
    for (int j = 0; j < block; ++j)
      x.col(j) = solver.solve(mass.cwiseProduct(ritz.vectors.col(j))).cwiseProduct(support);
    ritz = rayleigh_ritz(a, mass, x);
  }
  int degenerate = 1;
  while (degenerate < block &&
         ritz.values[degenerate] <= ritz.values[0] * (1 + kDegenerate) + 1e-300)
    ++degenerate;
  // One complex eigenvalue (z and i z): every combination is the same field turned.
  const Eigen::VectorXd field = degenerate <= 2
                                    ? Eigen::VectorXd(ritz.vectors.col(0))
                                    : most_uniform(ritz.vectors.leftCols(degenerate), mass, rows);
  return with_fixed_phase(field, mass, rows);
}

}  // namespace

Eigen::VectorXd smoothest_power_fields(
    const Eigen::SparseMatrix<double>& matrix,
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& solver, const Eigen::VectorXd& mass,
    const std::vector<std::vector<Index>>& component_rows, const Progress& progress) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(mass.size());
  for (const std::vector<Index>& rows : component_rows)
    if (!rows.empty()) z += smoothest_on_component(matrix, solver, mass, rows, progress);
  return z;
}

}  // namespace tessera
