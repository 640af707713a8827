#include "mesh/weld.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "mesh/exact_welder.h"

namespace tessera {
namespace {

using Cell = std::array<std::int64_t, 3>;

// Open addressing from a cell to the latest vertex in it; vertices of one cell are chained.
class CellTable {
 public:
  explicit CellTable(std::size_t vertices)
      : mask_(std::bit_ceil(2 * vertices + 2) - 1),
        cells_(mask_ + 1),
        heads_(mask_ + 1, kNoIndex) {}

  // The slot of `cell`: the one holding it, or the empty one where it belongs.
  std::size_t slot(const Cell& cell) const {
    std::uint64_t h = static_cast<std::uint64_t>(cell[0]) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(cell[1]) * 0xC2B2AE3D27D4EB4Full + (h >> 29);
    h ^= static_cast<std::uint64_t>(cell[2]) * 0x165667B19E3779F9ull + (h >> 32);
    std::size_t s = static_cast<std::size_t>(h ^ (h >> 31)) & mask_;
    while (heads_[s] != kNoIndex && cells_[s] != cell) s = (s + 1) & mask_;
    return s;
  }
  Index head(std::size_t slot) const { return heads_[slot]; }
  void set(std::size_t slot, const Cell& cell, Index v) {
    cells_[slot] = cell;
    heads_[slot] = v;
  }

 private:
  std::size_t mask_;
  std::vector<Cell> cells_;
  std::vector<Index> heads_;
};

std::vector<Index> exact_targets(const std::vector<Eigen::Vector3d>& positions) {
  std::vector<Index> target(positions.size());
  Mesh unique;
  ExactWelder welder(unique);
  std::vector<Index> first;  // unique position -> its first vertex
  for (Index v = 0; v < positions.size(); ++v) {
    const Index u = welder.vertex(positions[v]);
    if (u == first.size()) first.push_back(v);
    target[v] = first[u];
  }
  return target;
}

}  // namespace

std::vector<Index> weld_targets(const std::vector<Eigen::Vector3d>& positions, double tolerance) {
  if (!(tolerance > 0)) return exact_targets(positions);
  std::vector<Index> target(positions.size());
  if (positions.empty()) return target;
  Eigen::Vector3d origin = positions.front();
  for (const Eigen::Vector3d& p : positions) origin = origin.cwiseMin(p);
  const double width = 2 * tolerance;
  const double squared = tolerance * tolerance;
  CellTable table(positions.size());
  std::vector<Index> next_in_cell(positions.size(), kNoIndex);
  for (Index v = 0; v < positions.size(); ++v) {
    const Eigen::Vector3d& p = positions[v];
    const Eigen::Vector3d scaled = (p - origin) / width;
    Cell cell;
    Cell toward;  // per axis, the neighbour cell the tolerance ball can reach
    for (int i = 0; i < 3; ++i) {
      const double floor = std::floor(scaled[i]);
      cell[i] = static_cast<std::int64_t>(floor);
      toward[i] = scaled[i] - floor < 0.5 ? -1 : 1;
    }
    target[v] = v;
    for (int corner = 0; corner < 8 && target[v] == v; ++corner) {
      Cell probe = cell;
      for (int i = 0; i < 3; ++i)
        if (corner >> i & 1) probe[i] += toward[i];
      for (Index u = table.head(table.slot(probe)); u != kNoIndex; u = next_in_cell[u]) {
        if ((positions[u] - p).squaredNorm() <= squared) {
          target[v] = u;
          break;
        }
      }
    }
    if (target[v] != v) continue;
    const std::size_t slot = table.slot(cell);
    next_in_cell[v] = table.head(slot);
    table.set(slot, cell, v);
  }
  return target;
}

}  // namespace tessera
