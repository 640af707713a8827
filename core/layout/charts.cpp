#include "layout/charts.h"

#include <algorithm>

#include "param/poisson.h"

namespace tessera::layout {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

Eigen::Vector2d Charts::direction_across(Index h, const Eigen::Vector2d& d) const {
  return quarter_turns(d, param.rotation[h]);
}

Eigen::Vector2d Charts::point_on_halfedge(Index h, double t) const {
  return (1 - t) * uv(h) + t * uv(connectivity.next[h]);
}

double Charts::signed_area(Index f) const {
  const Index c = first_corner(f);
  return cross(uv(c + 1) - uv(c), uv(c + 2) - uv(c));
}

double Charts::tolerance(Index f) const {
  const Index c = first_corner(f);
  const double longest = std::max(
      {(uv(c + 1) - uv(c)).norm(), (uv(c + 2) - uv(c + 1)).norm(), (uv(c) - uv(c + 2)).norm()});
  return 1e-9 * longest;
}

}  // namespace tessera::layout
