#include "matching/probing.h"

namespace tessera::matching {

namespace {

constexpr std::uint32_t kEdgesPerClockRead = 64;

// One pass over the free edges; true if an edge was fixed.
bool probe_free_edges(Propagation& propagation, std::chrono::steady_clock::time_point deadline,
                      Probing& result) {
  bool changed = false;
  result.implied.clear();
  for (std::uint32_t e = 0; e < propagation.values().size() && !propagation.infeasible(); ++e) {
    if (e % kEdgesPerClockRead == 0 && std::chrono::steady_clock::now() >= deadline) {
      result.stopped = true;
      return changed;
    }
    if (propagation.values()[e] != Fixed::free) continue;
    if (!propagation.try_one(e)) {
      propagation.fix_zero(e);
      changed = true;
      continue;
    }
    // The direct drops are e's exclusive edges; the rest are implied exclusions.
    const std::vector<std::uint32_t>& dropped = propagation.dropped();
    for (std::size_t k = propagation.direct_drops(); k < dropped.size(); ++k) {
      result.implied.emplace_back(e, dropped[k]);
      result.implied.emplace_back(dropped[k], e);
    }
  }
  return changed;
}

}  // namespace

Probing probe(const MatchingProblem& problem, const Adjacency& incident, const Adjacency& exclusive,
              std::chrono::steady_clock::time_point deadline) {
  Propagation propagation(problem, incident, exclusive);
  Probing result;
  bool changed = true;
  while (changed && !propagation.infeasible() && !result.stopped) {
    changed = propagation.force_single_edges();
    if (!propagation.infeasible())
      changed = probe_free_edges(propagation, deadline, result) || changed;
  }
  result.infeasible = propagation.infeasible();
  if (result.infeasible) result.implied.clear();
  result.edges = propagation.values();
  return result;
}

}  // namespace tessera::matching
