#include "regmap/map_isomorphism.h"

namespace tessera::regmap {

namespace {

// The isomorphism that sends dart 0 to `image`, grown along next and opposite, if consistent.
std::optional<std::vector<std::int32_t>> grow_from(const RotationSystem& from,
                                                   const RotationSystem& to, std::int32_t image) {
  const std::size_t n = from.next_around.size();
  std::vector<std::int32_t> phi(n, -1), preimage(n, -1);
  std::vector<std::int32_t> stack = {0};
  phi[0] = image;
  preimage[static_cast<std::size_t>(image)] = 0;
  while (!stack.empty()) {
    const auto d = static_cast<std::size_t>(stack.back());
    stack.pop_back();
    const auto fd = static_cast<std::size_t>(phi[d]);
    for (const auto& [a, b] : {std::pair{from.next_around[d], to.next_around[fd]},
                               std::pair{from.opposite[d], to.opposite[fd]}}) {
      const auto x = static_cast<std::size_t>(a);
      if (phi[x] < 0) {
        if (preimage[static_cast<std::size_t>(b)] >= 0) return std::nullopt;
        phi[x] = b;
        preimage[static_cast<std::size_t>(b)] = a;
        stack.push_back(a);
      } else if (phi[x] != b) {
        return std::nullopt;
      }
    }
  }
  for (std::int32_t x : phi)
    if (x < 0) return std::nullopt;  // `from` is not connected
  return phi;
}

}  // namespace

std::optional<std::vector<std::int32_t>> find_map_isomorphism(const RotationSystem& from,
                                                              const RotationSystem& to) {
  const std::size_t n = from.next_around.size();
  if (n == 0 || n != to.next_around.size() || n != from.opposite.size() || n != to.opposite.size())
    return std::nullopt;
  for (std::size_t image = 0; image < n; ++image)
    if (auto phi = grow_from(from, to, static_cast<std::int32_t>(image))) return phi;
  return std::nullopt;
}

}  // namespace tessera::regmap
