#include "regmap/triangle_tiling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <queue>

#include "base/error.h"

namespace tessera::regmap {

using enum Letter;

const Word& side_word(Side side) {
  static const std::array<Word, 3> words = {Word{T}, Word{T, S}, Word{R, T}};
  return words[index(side)];
}

std::array<Corner, 2> side_corners(Side side) {
  switch (side) {
    case Side::MN:
      return {kM, kN};
    case Side::NO:
      return {kN, kO};
    case Side::MO:
      return {kM, kO};
  }
  return {kM, kN};
}

namespace {

// A face waiting to be placed: entered through `entry`, the neighbour across an N O side of the
// placed triangle `from`; ordered by the distance of its centre from the origin, then by `entry`.
// Faces related by a symmetry of the tiling are equally far in exact arithmetic, but their
// computed distances differ in the last bits, and differently with each platform's sin, cos and
// cosh: the distance is compared in steps of kDistanceStep, so that such ties go by `entry` and the
// native and wasm builds grow the same polygon.
constexpr double kDistanceStep = 1e-9;

struct Candidate {
  std::int64_t distance;  // in steps of kDistanceStep
  Element entry;
  Element from;
  bool operator>(const Candidate& other) const {
    return distance != other.distance ? distance > other.distance : entry > other.entry;
  }
};

class TilingBuilder {
 public:
  TilingBuilder(const FiniteGroup& group, const Progress& progress)
      : group_(group), progress_(progress) {
    tiling_.p = group.p;
    tiling_.q = group.q;
    tiling_.base = fundamental_triangle(group.p, group.q);
    const Geometry g = tiling_.geometry();
    const FundamentalTriangle& d = tiling_.base;
    reflection_ = {d.t, compose(g, d.t, d.s), compose(g, d.r, d.t)};
    const std::size_t n = group.order();
    tiling_.placement.resize(n);
    tiling_.corners.resize(n);
    tiling_.parent.assign(n, -1);
    tiling_.neighbour.resize(n);
    tiling_.open.assign(n, {false, false, false});
    placed_.assign(n, false);
    for (std::size_t e = 0; e < n; ++e) {
      for (Side side : kSides)
        tiling_.neighbour[e][index(side)] = group.times(static_cast<Element>(e), side_word(side));
    }
  }

  TriangleTiling build() {
    place_root();
    grow_faces();
    find_open_sides();
    pair_open_sides();
    return std::move(tiling_);
  }

 private:
  const Isometry& reflection(Side side) const { return reflection_[index(side)]; }

  void place_root() {
    tiling_.placement[0] = Isometry{};
    tiling_.corners[0] = tiling_.base.corners;
    placed_[0] = true;
    placed_count_ = 1;
    fill_face(0);
  }

  // Places h = g * side_word(side) as the reflection of g's triangle in that side.
  void place_across(Element g, Side side) {
    const Element h = tiling_.neighbour[static_cast<std::size_t>(g)][index(side)];
    const auto hi = static_cast<std::size_t>(h), gi = static_cast<std::size_t>(g);
    const Geometry geometry = tiling_.geometry();
    tiling_.placement[hi] = compose(geometry, tiling_.placement[gi], reflection(side));
    tiling_.parent[hi] = g;
    for (int k = 0; k < 3; ++k)
      tiling_.corners[hi][k] =
          apply(geometry, tiling_.placement[hi], tiling_.base.corners[static_cast<std::size_t>(k)]);
    for (Corner k : side_corners(side)) tiling_.corners[hi][k] = tiling_.corners[gi][k];
    placed_[hi] = true;
    ++placed_count_;
  }

  // Places the rest of the face of `entry` (all its triangles around M, through the M N and M O
  // sides) and queues the faces beyond its N O sides.
  void fill_face(Element entry) {
    std::vector<Element> face = {entry};
    for (std::size_t k = 0; k < face.size(); ++k) {
      for (Side side : {Side::MN, Side::MO}) {
        const Element h = tiling_.neighbour[static_cast<std::size_t>(face[k])][index(side)];
        if (placed_[static_cast<std::size_t>(h)]) continue;
        place_across(face[k], side);
        face.push_back(h);
      }
    }
    for (Element g : face) queue_face_beyond(g);
  }

  void queue_face_beyond(Element g) {
    const Element h = tiling_.neighbour[static_cast<std::size_t>(g)][index(Side::NO)];
    if (placed_[static_cast<std::size_t>(h)]) return;
    const Geometry geometry = tiling_.geometry();
    const Isometry there =
        compose(geometry, tiling_.placement[static_cast<std::size_t>(g)], reflection(Side::NO));
    const Point centre = apply(geometry, there, tiling_.base.corners[kM]);
    candidates_.push({std::llround(distance(geometry, Point{}, centre) / kDistanceStep), h, g});
  }

  void grow_faces() {
    while (!candidates_.empty()) {
      const Candidate next = candidates_.top();
      candidates_.pop();
      if (placed_[static_cast<std::size_t>(next.entry)]) continue;
      place_across(next.from, Side::NO);
      fill_face(next.entry);
      progress_.step("hyperbolic tiling",
                     static_cast<double>(placed_count_) / static_cast<double>(group_.order()));
    }
    if (placed_count_ != group_.order())
      throw Error("the tiling placed " + std::to_string(placed_count_) + " of " +
                  std::to_string(group_.order()) + " triangles (an internal error)");
  }

  // A side is shared when the neighbour's triangle has the same two corners there; distinct
  // triangles' corners are at least a side length apart, so a loose tolerance is safe.
  void find_open_sides() {
    const Geometry geometry = tiling_.geometry();
    const auto& c = tiling_.base.corners;
    const double tolerance =
        1e-6 * std::min({distance(geometry, c[kM], c[kN]), distance(geometry, c[kN], c[kO]),
                         distance(geometry, c[kM], c[kO])});
    for (std::size_t g = 0; g < tiling_.size(); ++g) {
      for (Side side : kSides) {
        const auto h = static_cast<std::size_t>(tiling_.neighbour[g][index(side)]);
        bool shared = true;
        for (Corner k : side_corners(side))
          shared = shared &&
                   distance(geometry, tiling_.corners[g][k], tiling_.corners[h][k]) < tolerance;
        tiling_.open[g][index(side)] = !shared;
      }
    }
  }

  void pair_open_sides() {
    const Geometry geometry = tiling_.geometry();
    for (std::size_t g = 0; g < tiling_.size(); ++g) {
      for (Side side : kSides) {
        const Element h = tiling_.neighbour[g][index(side)];
        if (!tiling_.open[g][index(side)] || static_cast<Element>(g) >= h) continue;
        const Isometry pairing =
            compose(geometry, compose(geometry, tiling_.placement[g], reflection(side)),
                    inverse(geometry, tiling_.placement[static_cast<std::size_t>(h)]));
        tiling_.pairs.push_back({static_cast<Element>(g), h, side, pairing});
      }
    }
  }

  const FiniteGroup& group_;
  const Progress& progress_;
  TriangleTiling tiling_;
  std::array<Isometry, 3> reflection_;  // the reflections in the sides of D0, by side
  std::vector<bool> placed_;
  std::size_t placed_count_ = 0;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> candidates_;
};

// Union-find over the 3|G| triangle corners.
class CornerClasses {
 public:
  explicit CornerClasses(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::size_t> parent_;
};

std::size_t corner_id(std::size_t g, Corner k) {
  return 3 * g + k;
}

}  // namespace

TriangleTiling build_tiling(const FiniteGroup& group, const Limits& limits,
                            const Progress& progress) {
  check_limit(group.order(), limits.max_tiling_triangles,
              "the tiling of a group of order " + std::to_string(group.order()) + " (triangles)",
              "--max-triangles");
  return TilingBuilder(group, progress).build();
}

PolygonShape polygon_shape(const TriangleTiling& tiling) {
  const std::size_t n = tiling.size();
  CornerClasses corners(3 * n);
  std::size_t open_sides = 0;
  for (std::size_t g = 0; g < n; ++g) {
    for (Side side : kSides) {
      if (tiling.open[g][index(side)]) {
        ++open_sides;
        continue;
      }
      const auto h = static_cast<std::size_t>(tiling.neighbour[g][index(side)]);
      for (Corner k : side_corners(side)) corners.unite(corner_id(g, k), corner_id(h, k));
    }
  }
  PolygonShape shape;
  for (std::size_t c = 0; c < 3 * n; ++c) shape.vertices += corners.find(c) == c;
  shape.faces = n;
  shape.boundary_edges = open_sides;
  shape.edges = (3 * n - open_sides) / 2 + open_sides;
  shape.euler = static_cast<long long>(shape.vertices) - static_cast<long long>(shape.edges) +
                static_cast<long long>(shape.faces);
  // Boundary cycles: components of the graph of open sides on the corner classes.
  CornerClasses boundary(3 * n);
  std::vector<bool> on_boundary(3 * n, false);
  for (std::size_t g = 0; g < n; ++g) {
    for (Side side : kSides) {
      if (!tiling.open[g][index(side)]) continue;
      const auto [a, b] = side_corners(side);
      const std::size_t ca = corners.find(corner_id(g, a)), cb = corners.find(corner_id(g, b));
      boundary.unite(ca, cb);
      on_boundary[ca] = on_boundary[cb] = true;
    }
  }
  for (std::size_t c = 0; c < 3 * n; ++c)
    shape.boundary_cycles += on_boundary[c] && boundary.find(c) == c;
  return shape;
}

}  // namespace tessera::regmap
