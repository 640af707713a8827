#include "param/linear_elimination.h"

#include <algorithm>
#include <cmath>

namespace tessera {
namespace {

using Row = LinearElimination::Row;

// Sorted by variable, duplicates summed, (relatively) zero coefficients dropped.
void normalize(Row& row) {
  std::sort(row.begin(), row.end());
  Row merged;
  for (const auto& [v, a] : row) {
    if (!merged.empty() && merged.back().first == v)
      merged.back().second += a;
    else
      merged.emplace_back(v, a);
  }
  double largest = 0;
  for (const auto& term : merged) largest = std::max(largest, std::abs(term.second));
  std::erase_if(merged, [&](const auto& term) { return std::abs(term.second) <= 1e-12 * largest; });
  row = std::move(merged);
}

}  // namespace

LinearElimination::LinearElimination(std::size_t variable_count)
    : expression_(variable_count), eliminated_(variable_count, 0), users_(variable_count) {}

bool LinearElimination::add(const Row& row) {
  Row reduced;
  for (const auto& [v, a] : row) {
    if (!eliminated_[v]) {
      reduced.emplace_back(v, a);
      continue;
    }
    for (const auto& [w, b] : expression_[v]) reduced.emplace_back(w, a * b);
  }
  normalize(reduced);
  if (reduced.empty()) return false;

  auto pivot = reduced.begin();
  for (auto it = reduced.begin(); it != reduced.end(); ++it)
    if (std::abs(it->second) > std::abs(pivot->second)) pivot = it;
  const Index p = pivot->first;
  const double scale = -1.0 / pivot->second;
  Row expression;
  for (const auto& [v, a] : reduced)
    if (v != p) expression.emplace_back(v, a * scale);

  // Keep every stored expression free of p.
  for (Index user : users_[p]) {
    Row& target = expression_[user];
    const auto it = std::find_if(target.begin(), target.end(),
                                 [p](const auto& term) { return term.first == p; });
    if (it == target.end()) continue;
    const double coefficient = it->second;
    target.erase(it);
    for (const auto& [v, a] : expression) {
      target.emplace_back(v, coefficient * a);
      users_[v].push_back(user);
    }
    normalize(target);
  }
  users_[p].clear();
  for (const auto& term : expression) users_[term.first].push_back(p);
  expression_[p] = std::move(expression);
  eliminated_[p] = 1;
  return true;
}

Eigen::SparseMatrix<double> LinearElimination::basis(std::size_t rows) const {
  std::vector<Index> column(eliminated_.size(), kNoIndex);
  for (Index v = 0; v < rows; ++v) {
    if (!eliminated_[v]) column[v] = 0;
    for (const auto& term : expression_[v]) column[term.first] = 0;
  }
  Index columns = 0;
  for (Index& c : column)
    if (c != kNoIndex) c = columns++;
  std::vector<Eigen::Triplet<double>> triplets;
  for (Index v = 0; v < rows; ++v) {
    if (!eliminated_[v]) triplets.emplace_back(v, column[v], 1.0);
    for (const auto& [w, a] : expression_[v]) triplets.emplace_back(v, column[w], a);
  }
  Eigen::SparseMatrix<double> p(static_cast<Eigen::Index>(rows), columns);
  p.setFromTriplets(triplets.begin(), triplets.end());
  return p;
}

}  // namespace tessera
