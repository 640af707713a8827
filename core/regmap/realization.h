// Which surface a map is drawn on (thesis Sec. 9.6, "automatic realization"): every target of
// the map's genus is tried and the pairings ranked. A hosohedral surface (two junctions) shows
// least of the map, so it comes last; then pairings by reflections (the drawing keeps T's
// mirrors) before rotation pairings, each by its quadrilateral's distortion; then more junctions.
#pragma once

#include <string>
#include <vector>

#include "base/limits.h"
#include "regmap/element_words.h"
#include "regmap/finite_group.h"
#include "regmap/pairing.h"
#include "regmap/target_maps.h"

namespace tessera::regmap {

struct Realization {
  TargetMap target;
  Pairing pairing;   // the target's best pairing
  double score = 0;  // lower is better (see above)
};

struct RealizationSearch {
  std::vector<Realization> found;  // best first
  std::vector<std::string> tried;  // every target searched, in order
  bool stopped = false;            // some search hit its work limit
};

double realization_score(const TargetMap& target, const Pairing& pairing);

// Searches `targets` (those of other genus are skipped) for pairings with M; each target's
// group is enumerated under `limits`.
RealizationSearch find_realizations(const FiniteGroup& source, const ElementWords& words, int genus,
                                    const std::vector<TargetMap>& targets,
                                    const PairingLimits& pairing_limits, const Limits& limits);

}  // namespace tessera::regmap
