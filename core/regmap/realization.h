// Which surface a map is drawn on (thesis Sec. 9.6, "automatic realization"): every target of
// the map's genus is tried and the pairings ranked. A hosohedral surface (two junctions) shows
// least of the map, so it comes last; then pairings by reflections (the drawing keeps T's
// mirrors) before rotation pairings, each by its quadrilateral's distortion; then more junctions.
// The ranked pairings are then drawn until one is right (draw_first_right, mapped_export.h): a
// pairing can pass every test of the search and still not glue, and a surface that crosses itself
// is passed over for the next one that does not.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/limits.h"
#include "regmap/element_words.h"
#include "regmap/finite_group.h"
#include "regmap/pairing.h"
#include "regmap/regular_surface.h"
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
  std::size_t drawn_wrong = 0;     // pairings that draw_first_right dropped
};

// Pairings kept per target: the search's next ones when the best does not draw.
inline constexpr std::size_t kPairingsPerTarget = 8;

double realization_score(const TargetMap& target, const Pairing& pairing);

// Targets' groups, enumerated once each (a batch over the catalog meets every target often).
class TargetGroups {
 public:
  explicit TargetGroups(const Limits& limits) : limits_(limits) {}
  const FiniteGroup& group(const TargetMap& target);

 private:
  Limits limits_;
  std::map<std::string, FiniteGroup> groups_;
};

// Targets' regular surfaces, built once each as for drawing (searched for crossings: their
// stats.self_intersections, which a drawing on them has too, since it subdivides the surface).
class TargetSurfaces {
 public:
  explicit TargetSurfaces(const Limits& limits) : limits_(limits) {}
  const RegularSurface& surface(const TargetMap& target, TargetGroups& groups);

 private:
  Limits limits_;
  std::map<std::string, RegularSurface> surfaces_;
};

// Searches `targets` (those of other genus are skipped) for pairings with M: each target's
// kPairingsPerTarget best, all ranked together.
RealizationSearch find_realizations(const FiniteGroup& source, const ElementWords& words, int genus,
                                    const std::vector<TargetMap>& targets,
                                    const PairingLimits& pairing_limits, TargetGroups& groups);

// A pairing as the manifest (data/regmaps/realizations.json) and the GLB's extras keep it:
// target, kind, x, y (a, b, c for reflections), apex, distortion, corners and mirrored as
// [re, im] pairs in the Poincare disk.
nlohmann::ordered_json pairing_json(const Pairing& pairing);
// Throws InputError naming the key when `json` is not such a pairing or an element is outside
// Sym(M) of order `source_order` (a manifest is a file, not trusted); the drawing checks the
// rest (that it glues and covers M once).
Pairing pairing_from_json(const nlohmann::json& json, std::size_t source_order);

}  // namespace tessera::regmap
