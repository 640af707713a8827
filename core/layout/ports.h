// Ports at the singularities (thesis Def. 2.3, 2.4; LAYOUT_NOTES "Charts and transitions"): walking
// counterclockwise around a vertex through its corners, applying the transitions, unfolds its
// one-ring into a cone of angle k * 90 degrees in parameter space; the axis directions of the
// charts in that cone are the isoline directions at the vertex. A singularity of valence k has k
// ports, numbered counterclockwise. On the boundary only the directions pointing into the surface
// are ports; the two along the boundary are not (Sec. 4.4).
//
// Where the injectivity constraints left a flipped triangle in a singularity's ring, the ring is
// folded and the isoline directions are the level-set branches that actually leave the vertex:
// per corner, the axis directions whose ray crosses the far edge (backwards in the flipped chart).
// Their number may then differ from the valence, and the branches that start backwards into the
// flipped chart are marked folded: their triangles are not flat, P1 may leave them unmatched.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "layout/charts.h"

namespace tessera::layout {

// The unfolded one-ring of a vertex: its corners counterclockwise with their signed chart angles,
// laid end to end. Angle `start` of a corner is the unfolded angle of its first edge (corner ->
// next corner); the unfolded angle of the first corner's first edge is its chart angle.
struct RingCorner {
  Index corner = kNoIndex;
  double start = 0;  // unfolded angle, radians
  double angle = 0;  // signed corner angle in the chart (negative in a flipped chart)
};

struct VertexRing {
  Index vertex = kNoIndex;
  bool boundary = false;  // the corners run from one boundary edge to the other
  std::vector<RingCorner> corners;
  double total = 0;  // the cone angle, sum of the corner angles
};

// The corner angles are the charts' signed angles; where the ring holds a flipped chart and they
// do not add up to `cone_angle` (the singularity's valence times 90 degrees), the flipped corner
// takes the missing full turns: it sweeps the long way round.
VertexRing vertex_ring(const Charts& charts, Index vertex, double cone_angle);

// The unit direction at unfolded angle `angle`, in the chart of the ring's corner `k`.
Eigen::Vector2d direction_in_corner(const Charts& charts, const VertexRing& ring, std::size_t k,
                                    double angle);
// The unfolded angle of a direction given in the chart of corner `k`, within that corner's range
// (up to a half turn beyond it either way).
double unfolded_angle(const Charts& charts, const VertexRing& ring, std::size_t k,
                      const Eigen::Vector2d& direction);
// The position in ring.corners of the corner a line leaving the vertex at unfolded angle `angle`
// starts in (corner_contains() holds for it), or ring.corners.size() if there is none (the angle
// points out of a boundary vertex or into a fold).
std::size_t corner_at_angle(const Charts& charts, const VertexRing& ring, double angle);

struct Port {
  Index singular_point = 0;  // index into Ports::points
  int number = 0;            // counterclockwise at its singular point
  double angle = 0;          // unfolded angle in the singular point's ring
  Index corner = kNoIndex;   // the corner halfedge the port's isoline starts in
  bool folded = false;       // that corner's chart is flipped (a folded ring)
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // axis-parallel, chart of face(corner)
};

struct SingularPoint {
  VertexRing ring;
  int valence = 0;           // of the singularity (cross_field.h)
  std::vector<Index> ports;  // global port ids, counterclockwise (only those into the surface)
  // On the boundary the ports do not close up: the neighbour of the last one is not the first.
  bool cyclic() const { return !ring.boundary; }
  // A stand-in node (ports.cpp, stand_in_nodes()): a regular boundary vertex, no singularity.
  bool stand_in() const { return ring.boundary && valence == 2; }
};

struct Ports {
  // One per singularity of the parameterization, same order, then the stand-in nodes of valence 2
  // of components with boundary but no singularity (ports.cpp, stand_in_nodes()).
  std::vector<SingularPoint> points;
  std::vector<Port> ports;
  std::vector<Index> point_of_vertex;  // per mesh vertex, its singular point or kNoIndex

  // The port next to `port` counterclockwise (step +1) or clockwise (step -1) at its singular
  // point, or kNoIndex where the boundary interrupts the order.
  Index neighbour(Index port, int step) const;
  // The port of singular point `point` whose unfolded angle is nearest to `angle` (mod the cone),
  // kNoIndex if none is within 45 degrees.
  Index nearest_port(Index point, double angle) const;
};

// The ports of every singularity of param: valence many at an interior one with an unfolded ring.
Ports find_ports(const Charts& charts);

}  // namespace tessera::layout
