// Straight lines of M_f traced through the charts (thesis Ch. 4 opening, Fig. 4.1; LAYOUT_NOTES
// "Tracing"): in the current triangle find the exit edge, map the exit point and the direction
// through the edge's transition, continue in the neighbour. Isolines (separatrices) and the
// hypotenuses of chosen edges (arcs) use the same walker.
//
// Degenerate passes are decided by one fixed rule, a symbolic shift of the line to its left: a
// vertex within the chart tolerance of the line counts as lying on its right. So a line through a
// vertex turns around it through the faces on its left (one zero-length step per face) and leaves
// through the face whose far edge it crosses; a line along an edge runs inside the face on its
// left. The side of the entry edge's endpoints is carried from face to face, never recomputed, so
// neighbouring faces always agree. Inside a flipped chart (a fold near a singularity) the line is
// the level set it is everywhere else: it leaves through the other edge it crosses.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "layout/charts.h"

namespace tessera::layout {

// A line passing a singularity closer than this (parametric units) runs into it. Beyond a cone
// point passed at the distance of the parameterization's noise a line's continuation is
// meaningless, and on a symmetric mesh singularities that should line up do so only to that noise.
inline constexpr double kNearSingularity = 1e-4;

// The side of a point relative to a directed line; `on` (within the tolerance) acts as `right`.
enum class Side : std::uint8_t { right, on, left };

// Where a traced line is: a point of face `face` in that face's chart, and how it got there.
struct LineCursor {
  Index face = kNoIndex;
  // The corner halfedge of `face` the line entered through, or the corner at which it starts.
  Index entry = kNoIndex;
  bool starts_at_corner = false;  // the line starts at the vertex of corner `entry`
  Side entry_from = Side::right;  // sides of the entry halfedge's endpoints (unused at a start)
  Side entry_to = Side::left;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // unit, in the chart of `face`
  double length = 0;                                    // parametric length traced so far
};

// The line's crossing of the current face.
struct LineStep {
  Index exit = kNoIndex;  // the corner halfedge of the face the line leaves through
  double t = 0;           // the exit point's parameter along `exit` (0 at its corner)
  Side exit_from = Side::right;
  Side exit_to = Side::left;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // the exit point, in the face's chart
  double length = 0;                                // |exit point - cursor point|
  Index vertex = kNoIndex;  // the mesh vertex the exit point is, when the line passes through one
  bool valid = false;       // false: the line does not cross the face (a start outside the corner)
};

// A cursor at the corner halfedge `corner`'s vertex heading along `direction` (unit, chart of
// face(corner)).
LineCursor cursor_at_corner(const Charts& charts, Index corner, const Eigen::Vector2d& direction);

// True if a line leaving corner `corner`'s vertex along `direction` crosses that corner's face
// (its far edge has one endpoint on each side).
bool corner_contains(const Charts& charts, Index corner, const Eigen::Vector2d& direction);

// The crossing of the cursor's face.
LineStep line_step(const Charts& charts, const LineCursor& cursor);

// Moves the cursor across the step's exit edge into the neighbouring face (point and direction
// through the transition, length advanced). Returns false, leaving the cursor, at the boundary.
bool cross_edge(const Charts& charts, const LineStep& step, LineCursor& cursor);

}  // namespace tessera::layout
