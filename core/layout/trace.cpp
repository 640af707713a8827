#include "layout/trace.h"

#include <algorithm>

namespace tessera::layout {
namespace {

bool is_left(Side s) {
  return s == Side::left;
}

struct SideTest {
  const Charts& charts;
  Eigen::Vector2d point;
  Eigen::Vector2d direction;
  double tolerance;

  double value(Index corner) const { return cross(direction, charts.uv(corner) - point); }
  Side side(Index corner) const {
    const double s = value(corner);
    return s > tolerance ? Side::left : s < -tolerance ? Side::right : Side::on;
  }
  // The signed distance of a corner with a known side, made to agree with that side.
  double agreeing_value(Index corner, Side known) const {
    const double s = value(corner);
    return known == Side::on ? 0.0 : known == Side::left ? std::max(s, 0.0) : std::min(s, 0.0);
  }
};

SideTest side_test(const Charts& charts, Index face, const Eigen::Vector2d& point,
                   const Eigen::Vector2d& direction) {
  return {charts, point, direction, charts.tolerance(face)};
}

// Fills the exit point of a step whose exit halfedge and endpoint sides are set.
void place_exit(const Charts& charts, const SideTest& test, const LineCursor& cursor,
                LineStep& step) {
  const Index to = charts.connectivity.next[step.exit];
  if (step.exit_from == Side::on) {
    step.t = 0;
    step.vertex = charts.vertex(step.exit);
  } else if (step.exit_to == Side::on) {
    step.t = 1;
    step.vertex = charts.vertex(to);
  } else {
    const double a = test.agreeing_value(step.exit, step.exit_from);
    const double b = test.agreeing_value(to, step.exit_to);
    step.t = a == b ? 0.5 : std::clamp(a / (a - b), 0.0, 1.0);
  }
  step.point = charts.point_on_halfedge(step.exit, step.t);
  step.length = (step.point - cursor.point).norm();
  step.valid = true;
}

}  // namespace

LineCursor cursor_at_corner(const Charts& charts, Index corner, const Eigen::Vector2d& direction) {
  LineCursor cursor;
  cursor.face = charts.connectivity.face[corner];
  cursor.entry = corner;
  cursor.starts_at_corner = true;
  cursor.point = charts.uv(corner);
  cursor.direction = direction;
  return cursor;
}

bool corner_contains(const Charts& charts, Index corner, const Eigen::Vector2d& direction) {
  const Connectivity& c = charts.connectivity;
  const SideTest test = side_test(charts, c.face[corner], charts.uv(corner), direction);
  const Index a = c.next[corner], b = c.prev[corner];
  const Side side_a = test.side(a), side_b = test.side(b);
  if (is_left(side_a) == is_left(side_b)) return false;
  // The line crosses the far edge; the ray does if it crosses ahead (behind in a flipped chart,
  // whose orientation is reversed).
  const double sa = test.agreeing_value(a, side_a), sb = test.agreeing_value(b, side_b);
  const Eigen::Vector2d crossing = charts.uv(a) + (sa / (sa - sb)) * (charts.uv(b) - charts.uv(a));
  const double ahead = (crossing - charts.uv(corner)).dot(direction);
  return charts.signed_area(c.face[corner]) > 0 ? ahead > 0 : ahead < 0;
}

LineStep line_step(const Charts& charts, const LineCursor& cursor) {
  const Connectivity& c = charts.connectivity;
  const SideTest test = side_test(charts, cursor.face, cursor.point, cursor.direction);
  LineStep step;
  if (cursor.starts_at_corner) {
    step.exit = c.next[cursor.entry];
    step.exit_from = test.side(step.exit);
    step.exit_to = test.side(c.next[step.exit]);
    if (is_left(step.exit_from) == is_left(step.exit_to)) return step;
  } else {
    // Entered through halfedge x -> y; the third corner z decides which other edge is crossed.
    const Index z = c.prev[cursor.entry];
    const Side side_z = test.side(z);
    if (is_left(side_z) == is_left(cursor.entry_from)) {
      step.exit = c.next[cursor.entry];  // y -> z
      step.exit_from = cursor.entry_to;
      step.exit_to = side_z;
    } else {
      step.exit = z;  // z -> x
      step.exit_from = side_z;
      step.exit_to = cursor.entry_from;
    }
  }
  place_exit(charts, test, cursor, step);
  return step;
}

bool cross_edge(const Charts& charts, const LineStep& step, LineCursor& cursor) {
  const Connectivity& c = charts.connectivity;
  const Index twin = c.twin[step.exit];
  if (c.is_boundary_halfedge(twin)) return false;
  cursor.face = c.face[twin];
  cursor.entry = twin;
  cursor.starts_at_corner = false;
  cursor.entry_from = step.exit_to;
  cursor.entry_to = step.exit_from;
  cursor.point = charts.point_on_halfedge(twin, 1 - step.t);
  cursor.direction = charts.direction_across(step.exit, cursor.direction);
  cursor.length += step.length;
  return true;
}

}  // namespace tessera::layout
