// Welding of bit-identical positions (with -0 taken as +0) into one vertex, for the formats that
// repeat a shared vertex instead of indexing it: STL (per triangle) and glTF (per attribute split).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <unordered_map>

#include "mesh/mesh.h"

namespace tessera {

class ExactWelder {
 public:
  explicit ExactWelder(Mesh& mesh) : mesh_(mesh) {}

  // The vertex at exactly p, added to the mesh if there is none yet.
  Index vertex(const Eigen::Vector3d& p) {
    Key key;
    for (int i = 0; i < 3; ++i) {
      const double x = p[i] + 0.0;  // -0.0 + 0.0 is +0.0
      std::memcpy(&key[i], &x, sizeof x);
    }
    const auto [it, inserted] = index_.try_emplace(key, static_cast<Index>(mesh_.vertex_count()));
    if (inserted) mesh_.add_vertex(p);
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
      h ^= k[1] + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
      h ^= k[2] + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };

  Mesh& mesh_;
  std::unordered_map<Key, Index, KeyHash> index_;
};

}  // namespace tessera
