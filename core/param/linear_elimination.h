// Homogeneous linear equality constraints eliminated one at a time (Gaussian elimination on sparse
// rows), so that every solution is x = P y over the variables left free. The seamless
// parameterization uses it for the transition constraints (A.7), (A.8): the solve then runs over y
// with P^T Q P, and every constraint holds exactly up to rounding. Constraints implied by earlier
// ones (a transition met twice around a cut-graph node) are recognized and dropped.
//
// Pivot: the largest coefficient of the reduced row, the lowest variable among equals (so the
// result is deterministic). Expressions are kept in terms of the currently free variables.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Sparse>

#include "mesh/mesh.h"

namespace tessera {

class LinearElimination {
 public:
  using Row = std::vector<std::pair<Index, double>>;  // sum of coefficient * variable

  explicit LinearElimination(std::size_t variable_count);

  // Adds the constraint row == 0; returns false if it was implied by the earlier ones.
  bool add(const Row& row);

  // P restricted to variables [0, rows): one column per free variable that occurs there, in
  // increasing variable order.
  Eigen::SparseMatrix<double> basis(std::size_t rows) const;

 private:
  std::vector<Row> expression_;  // per eliminated variable, sorted, over free ones
  std::vector<std::uint8_t> eliminated_;
  std::vector<std::vector<Index>> users_;  // per free variable: eliminated ones mentioning it
};

}  // namespace tessera
