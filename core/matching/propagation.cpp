#include "matching/propagation.h"

namespace tessera::matching {

Propagation::Propagation(const MatchingProblem& problem, const Adjacency& incident,
                         const Adjacency& exclusive, const std::vector<Fixed>& start)
    : problem_(problem),
      incident_(incident),
      exclusive_(exclusive),
      values_(start.empty() ? std::vector<Fixed>(problem.edges.size(), Fixed::free) : start),
      matched_(problem.node_count(), 0),
      covered_(problem.node_count(), 0),
      zero_(problem.edges.size(), 0),
      one_(problem.edges.size(), 0) {
  for (std::uint32_t e = 0; e < values_.size(); ++e)
    if (values_[e] == Fixed::one) matched_[problem.edges[e].u] = matched_[problem.edges[e].v] = 1;
}

bool Propagation::force(std::uint32_t g) {
  if (zero_[g] == stamp_) return false;
  one_[g] = stamp_;
  forced_.push_back(g);
  covered_[problem_.edges[g].u] = covered_[problem_.edges[g].v] = stamp_;
  for (std::uint32_t h : exclusive_.of(g)) {
    if (one_[h] == stamp_ || values_[h] == Fixed::one) return false;
    if (values_[h] != Fixed::free || zero_[h] == stamp_) continue;
    zero_[h] = stamp_;
    dropped_.push_back(h);
    queue_.push_back(problem_.edges[h].u);
    queue_.push_back(problem_.edges[h].v);
  }
  return true;
}

std::uint32_t Propagation::usable_edges(std::uint32_t p, std::uint32_t& last) const {
  std::uint32_t usable = 0;
  for (std::uint32_t f : incident_.of(p)) {
    if (values_[f] != Fixed::free || zero_[f] == stamp_) continue;
    last = f;
    if (++usable == 2) break;
  }
  return usable;
}

bool Propagation::try_one(std::uint32_t e) {
  ++stamp_;
  dropped_.clear();
  forced_.clear();
  queue_.clear();
  if (values_[e] != Fixed::free || !force(e)) return false;
  direct_drops_ = dropped_.size();
  for (std::size_t next = 0; next < queue_.size(); ++next) {
    const std::uint32_t p = queue_[next];
    if (problem_.is_virtual[p] || matched_[p] || covered_[p] == stamp_) continue;
    std::uint32_t last = 0;
    const std::uint32_t usable = usable_edges(p, last);
    if (usable == 0 || (usable == 1 && !force(last))) return false;
  }
  return true;
}

void Propagation::commit() {
  for (std::uint32_t h : dropped_) values_[h] = Fixed::zero;
  for (std::uint32_t g : forced_) {
    values_[g] = Fixed::one;
    matched_[problem_.edges[g].u] = matched_[problem_.edges[g].v] = 1;
  }
  dropped_.clear();
  forced_.clear();
}

void Propagation::check_port(std::uint32_t p) {
  if (infeasible_ || problem_.is_virtual[p] || matched_[p]) return;
  ++stamp_;  // no try in progress: count the committed state
  std::uint32_t last = 0;
  const std::uint32_t usable = usable_edges(p, last);
  if (usable == 0) {
    infeasible_ = true;
  } else if (usable == 1) {
    if (try_one(last)) {
      commit();
    } else {
      infeasible_ = true;
    }
  }
}

void Propagation::fix_zero(std::uint32_t e) {
  if (values_[e] == Fixed::one) infeasible_ = true;
  if (values_[e] != Fixed::free) return;
  values_[e] = Fixed::zero;
  check_port(problem_.edges[e].u);
  check_port(problem_.edges[e].v);
}

void Propagation::restore(const State& state) {
  values_ = state.values;
  matched_ = state.matched;
  infeasible_ = state.infeasible;
}

bool Propagation::force_single_edges() {
  bool changed = false;
  for (std::uint32_t v = 0; v < problem_.node_count() && !infeasible_; ++v) {
    const bool was_matched = matched_[v] != 0;
    check_port(v);
    changed = changed || (!was_matched && matched_[v]);
  }
  return changed;
}

}  // namespace tessera::matching
