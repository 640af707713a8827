// Tri(G): the planar representation of a regular map (thesis Sec. 9.3, Fig. 9.7 and 9.8).
//
// One triangle per group element g, the image of the fundamental triangle D0 under the isometry
// P_g; g and g*X are neighbours across the side that X reflects in (T: M N, T*S: N O, R*T: M O).
// The triangles are grown from the identity one face of the map at a time (its 2p triangles around
// the face centre), the next face always the one whose centre is nearest the origin, each placed
// across a map edge (an N O side) of a placed triangle. Every element is placed exactly once, so
// the result is a connected polygon of whole faces without overlaps (distinct elements are distinct
// triangles of the universal cover) whose open sides are map edges, and an open side of g is paired
// with the same side of its table neighbour h = g*X by the isometry P_g X P_h^-1 (Fig. 9.8b).
//
// Positions: P_g = P_parent X, one renormalized product per step (tiling depth is logarithmic in
// |G| in the hyperbolic plane), and the two corners a triangle shares with its parent are copied,
// so tree neighbours share corners exactly. Works in all three geometries: the Poincare disk, the
// Euclidean plane (torus maps: the polygon is a fundamental domain of translations) and the sphere
// (Platonic maps: the polygon closes up and nothing is paired).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/limits.h"
#include "base/progress.h"
#include "regmap/finite_group.h"
#include "regmap/isometry.h"

namespace tessera::regmap {

// A side of a triangle, named by its corners; the letter word reflecting in it is side_word().
enum class Side : std::uint8_t { MN, NO, MO };
inline constexpr std::array<Side, 3> kSides = {Side::MN, Side::NO, Side::MO};
enum Corner : std::uint8_t { kM = 0, kN = 1, kO = 2 };

const Word& side_word(Side side);               // T, T*S, R*T
std::array<Corner, 2> side_corners(Side side);  // its two corners
inline std::size_t index(Side side) {
  return static_cast<std::size_t>(side);
}

struct BoundaryPair {
  Element first = 0;  // first = second * side_word(side), first < second
  Element second = 0;
  Side side = Side::NO;
  Isometry pairing;  // maps second's side onto first's side, corner to corner
};

struct TriangleTiling {
  int p = 0;
  int q = 0;
  FundamentalTriangle base;
  std::vector<Isometry> placement;                // per element: D0 -> its triangle
  std::vector<std::array<Point, 3>> corners;      // per element: M, N, O
  std::vector<Element> parent;                    // placed from; -1 for the identity
  std::vector<std::array<Element, 3>> neighbour;  // per element and side: g * side_word(side)
  std::vector<std::array<bool, 3>> open;          // side not shared with its placed neighbour
  std::vector<BoundaryPair> pairs;

  Geometry geometry() const { return base.geometry; }
  std::size_t size() const { return placement.size(); }
};

// Throws LimitError when |G| is above limits.max_tiling_triangles (each triangle holds about 200
// bytes, and the picture one polygon per triangle).
TriangleTiling build_tiling(const FiniteGroup& group, const Limits& limits = Limits(),
                            const Progress& progress = Progress());

// The polygon as a cell complex (triangles glued along their shared sides): a disk has
// euler == 1 and one boundary cycle.
struct PolygonShape {
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  long long euler = 0;
  std::size_t boundary_edges = 0;
  std::size_t boundary_cycles = 0;
};
PolygonShape polygon_shape(const TriangleTiling& tiling);

}  // namespace tessera::regmap
