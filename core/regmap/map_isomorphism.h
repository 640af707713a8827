// Isomorphisms of maps given by rotation systems: darts with the next dart counterclockwise around
// their node and the other dart of their edge. Used to recognize a catalog map as one of the
// symmetric bases (platonic_base.h), whose rotation systems are built from geometry.
//
// In:  two rotation systems (next_around and opposite of equal sizes) of connected maps.
// Out: a dart bijection phi with phi(next(d)) = next'(phi(d)) and phi(opposite(d)) =
//      opposite'(phi(d)), or nothing. A connected map's isomorphism is fixed by the image of one
//      dart, so each image of dart 0 is tried: O(darts^2).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace tessera::regmap {

struct RotationSystem {
  std::vector<std::int32_t> next_around;
  std::vector<std::int32_t> opposite;
};

std::optional<std::vector<std::int32_t>> find_map_isomorphism(const RotationSystem& from,
                                                              const RotationSystem& to);

}  // namespace tessera::regmap
