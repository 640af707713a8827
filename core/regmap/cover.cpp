#include "regmap/cover.h"

namespace tessera::regmap {

bool same_point(Geometry g, const Point& z, const Point& w) {
  return distance(g, z, w) < kLengthTolerance;
}

Cover::Cover(const FiniteGroup& group)
    : group_(group), base_(fundamental_triangle(group.p, group.q)) {
  const Geometry g = base_.geometry;
  reflection_ = {base_.t, compose(g, base_.t, base_.s), compose(g, base_.r, base_.t)};
}

CoverTriangle Cover::across(const CoverTriangle& t, Side side) {
  ++steps_;
  return {group_.times(t.element, side_word(side)),
          compose(geometry(), t.placement, reflection_[index(side)])};
}

Isometry Cover::mirror(const CoverTriangle& t, Side side) const {
  const Geometry g = geometry();
  return compose(g, compose(g, t.placement, reflection_[index(side)]), inverse(g, t.placement));
}

}  // namespace tessera::regmap
