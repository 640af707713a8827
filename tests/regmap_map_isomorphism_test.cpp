// Map isomorphisms: a relabelled rotation system is found again; a different one of the same size
// is not.
#include <gtest/gtest.h>

#include "regmap/map_isomorphism.h"

namespace tessera::regmap {
namespace {

// The cube as a rotation system: darts (v, k) = 3v + k, vertices as 3-bit coordinates, the k-th
// neighbour flipping bit k.
RotationSystem cube() {
  RotationSystem r;
  for (int v = 0; v < 8; ++v) {
    const int parity = __builtin_popcount(static_cast<unsigned>(v)) % 2;
    for (int k = 0; k < 3; ++k) {
      // Counterclockwise order alternates with the parity of the vertex.
      r.next_around.push_back(3 * v + (parity ? (k + 2) % 3 : (k + 1) % 3));
      r.opposite.push_back(3 * (v ^ (1 << k)) + k);
    }
  }
  return r;
}

RotationSystem relabelled(const RotationSystem& r, const std::vector<std::int32_t>& to) {
  RotationSystem out;
  out.next_around.resize(r.next_around.size());
  out.opposite.resize(r.opposite.size());
  for (std::size_t d = 0; d < to.size(); ++d) {
    out.next_around[static_cast<std::size_t>(to[d])] =
        to[static_cast<std::size_t>(r.next_around[d])];
    out.opposite[static_cast<std::size_t>(to[d])] = to[static_cast<std::size_t>(r.opposite[d])];
  }
  return out;
}

TEST(MapIsomorphism, FindsARelabelling) {
  const RotationSystem a = cube();
  std::vector<std::int32_t> to(a.next_around.size());
  for (std::size_t d = 0; d < to.size(); ++d)
    to[d] = static_cast<std::int32_t>((7 * d + 5) % to.size());
  const RotationSystem b = relabelled(a, to);
  const auto phi = find_map_isomorphism(a, b);
  ASSERT_TRUE(phi.has_value());
  for (std::size_t d = 0; d < to.size(); ++d) {
    EXPECT_EQ(b.next_around[static_cast<std::size_t>((*phi)[d])],
              (*phi)[static_cast<std::size_t>(a.next_around[d])]);
    EXPECT_EQ(b.opposite[static_cast<std::size_t>((*phi)[d])],
              (*phi)[static_cast<std::size_t>(a.opposite[d])]);
  }
}

TEST(MapIsomorphism, TellsDifferentMapsApart) {
  const RotationSystem a = cube();
  RotationSystem b = a;
  // The same rotation at every vertex: a different map (its faces are not the cube's six).
  for (int v = 0; v < 8; ++v)
    for (int k = 0; k < 3; ++k)
      b.next_around[static_cast<std::size_t>(3 * v + k)] = 3 * v + (k + 1) % 3;
  EXPECT_FALSE(find_map_isomorphism(a, b).has_value());
  EXPECT_FALSE(find_map_isomorphism(a, RotationSystem{}).has_value());
}

}  // namespace
}  // namespace tessera::regmap
