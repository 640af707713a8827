// The arcs of a layout (thesis Sec. 4.1 end, Def. 2.6, 2.7; LAYOUT_NOTES "Edges, weights, arcs"): a
// chosen edge of G is the parametric geodesic homotopic to base + height. Its triangle being
// singularity-free, that geodesic is straight: in the chart of the base port it leaves the
// singularity along L_base d - L_height side J d (d the port's direction) and, traced through the
// charts like an isoline for sqrt(L_base^2 + L_height^2), ends at the far singularity, where it is
// snapped. Edges of height 0 are their separatrix (to a singularity or to the boundary).
//
// In:  the charts, the port graph and one of its edges. Out: the arc as pieces per face, each from
//      one surface point (a vertex or a point on an edge) to the next, and as a polyline; nothing
//      if the straight line misses its far singularity, or reaches it through another port's
//      sector (more than 22.5 degrees off the hypotenuse's angle there, where it would run along
//      that port's arc), that is, if the triangle is not singularity-free (Def. 2.7) after all:
//      the window reduction of Prop. 4.1 assumes the region around the triangle flat, which a
//      cluster of singularities inside it can defeat. On dragon (--sharp 180) 3 of 28,478 edges
//      came in through the wrong sector; none on the other shared meshes.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "layout/port_graph.h"

namespace tessera::layout {

// A point of the mesh: a vertex, or the point at parameter t along edge `edge` (from the origin of
// connectivity.edge_halfedge[edge], t in (0, 1)).
struct SurfacePoint {
  Index vertex = kNoIndex;
  Index edge = kNoIndex;
  double t = 0;
  bool operator==(const SurfacePoint&) const = default;
};

struct ArcPiece {
  Index face = 0;
  SurfacePoint from;
  SurfacePoint to;
  Eigen::Vector2d from_uv = Eigen::Vector2d::Zero();  // in the chart of face
  Eigen::Vector2d to_uv = Eigen::Vector2d::Zero();
};

struct Arc {
  Index edge = 0;                // of the port graph
  std::vector<ArcPiece> pieces;  // consecutive: each piece starts where the last one ended
  double length = 0;             // parametric
  // The rotation (radians, counterclockwise in uv) from the arc's direction to its base's: the
  // same in every chart, since the transitions are rotations. Measured where the arc starts, so
  // that a flipped chart there (which turns the hypotenuse the other way) is accounted for.
  double base_turn = 0;
};

std::optional<Arc> trace_arc(const Charts& charts, const PortGraph& graph, Index edge);

// Removes the edges whose arc is not straight (trace_arc() finds none), renumbering the rest and
// the zero-area pairs; returns the arcs of the edges kept, in edge order. Run before the conflicts
// are built.
std::vector<Arc> keep_edges_with_arcs(const Charts& charts, PortGraph& graph);

// The 3D position of a surface point.
Eigen::Vector3d position_of(const Mesh& mesh, const Connectivity& connectivity,
                            const SurfacePoint& point);
// The arc as a 3D polyline (its pieces' endpoints).
std::vector<Eigen::Vector3d> arc_polyline(const Mesh& mesh, const Connectivity& connectivity,
                                          const Arc& arc);

}  // namespace tessera::layout
