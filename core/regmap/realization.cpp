#include "regmap/realization.h"

#include <algorithm>
#include <cmath>

namespace tessera::regmap {

double realization_score(const TargetMap& target, const Pairing& pairing) {
  const double hosohedron = target.kind == TargetKind::Hosohedron ? 100.0 : 0.0;
  const double rotations = pairing.kind == PairingKind::Rotations ? 10.0 : 0.0;
  const double junctions = 1.0 / (1.0 + static_cast<double>(target.vertices));
  return hosohedron + rotations + std::min(pairing.distortion, 9.0) + junctions;
}

RealizationSearch find_realizations(const FiniteGroup& source, const ElementWords& words, int genus,
                                    const std::vector<TargetMap>& targets,
                                    const PairingLimits& pairing_limits, const Limits& limits) {
  RealizationSearch result;
  for (const TargetMap& t : targets) {
    if (t.surface_genus() != genus) continue;
    result.tried.push_back(t.name);
    const FiniteGroup group = enumerate_group(t.presentation, limits);
    const PairingSearch search =
        find_pairings(source, words, t.presentation, group, pairing_limits);
    result.stopped = result.stopped || search.stopped;
    if (search.pairings.empty()) continue;
    const Pairing& best = search.pairings.front();
    result.found.push_back({t, best, realization_score(t, best)});
  }
  std::stable_sort(result.found.begin(), result.found.end(),
                   [](const Realization& a, const Realization& b) { return a.score < b.score; });
  return result;
}

}  // namespace tessera::regmap
