// M's triangle tiling in the universal cover (thesis Sec. 9.3), walked triangle by triangle: the
// ground on which a target's quarter tube is found (pairing.h). A cover triangle is an element g
// of Sym(M) with its placement P_g (D0 -> its triangle); P_{g X} = P_g X for a letter X, so the
// symmetry h of M acts on the cover as P_h, and its element and isometry multiply alike.
#pragma once

#include <array>
#include <cstddef>

#include "regmap/finite_group.h"
#include "regmap/isometry.h"
#include "regmap/triangle_tiling.h"

namespace tessera::regmap {

inline constexpr double kLengthTolerance = 1e-6;  // hyperbolic lengths that count as equal

bool same_point(Geometry g, const Point& z, const Point& w);

// A triangle of M's tiling in the universal cover: its element and its placement (D0 -> it).
struct CoverTriangle {
  Element element = 0;
  Isometry placement;
};

class Cover {
 public:
  explicit Cover(const FiniteGroup& group);

  Geometry geometry() const { return base_.geometry; }
  const FundamentalTriangle& base() const { return base_; }

  CoverTriangle across(const CoverTriangle& t, Side side);
  Point corner(const CoverTriangle& t, Corner c) const {
    return apply(geometry(), t.placement, base_.corners[c]);
  }
  // The triangles on one side of a mirror line through a corner: the corner's angle is pi / that.
  int sectors(Corner c) const { return c == kM ? group_.p : c == kN ? group_.q : 2; }
  // The reflection in the line through t's side, as an isometry of the cover.
  Isometry mirror(const CoverTriangle& t, Side side) const;
  std::size_t steps() const { return steps_; }

 private:
  const FiniteGroup& group_;
  FundamentalTriangle base_;
  std::array<Isometry, 3> reflection_;
  std::size_t steps_ = 0;
};

}  // namespace tessera::regmap
