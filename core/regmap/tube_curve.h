// The centreline of an edge's tube (thesis Sec. 9.4, Fig. 9.11): the curve the tubification sweeps
// a ring along and the relaxation keeps apart from the others.
//
// A C1 chain of cubic Bezier arcs through the knots (the first dart's tube start, the edge's
// waypoints, the second dart's tube start). It leaves each junction along its dart with the
// junction's arm as control arm (less on a shorter first chord); at a waypoint its tangent is the
// direction between the neighbouring knots, with arms of 0.4 of the chords, so that a loop whose
// darts are opposite passes its midpoint parallel to them. The arcs up to the middle waypoint are
// the first dart's half, the rest the second's.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "regmap/embedded_graph.h"

namespace tessera::regmap {

struct Bezier {
  std::array<Eigen::Vector3d, 4> p;

  Eigen::Vector3d at(double t) const;
  Eigen::Vector3d derivative(double t) const;
};

// The unit vector along v, or `fallback` for a vector too short to have a direction.
Eigen::Vector3d unit_or(const Eigen::Vector3d& v, const Eigen::Vector3d& fallback);

std::vector<Bezier> edge_centreline(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                                    const JunctionOrder& order, std::size_t edge);

// The number of arcs of the first dart's half of an edge with `waypoints` waypoints.
inline std::size_t first_half_arcs(std::size_t waypoints) {
  return (waypoints + 1) / 2;
}

}  // namespace tessera::regmap
