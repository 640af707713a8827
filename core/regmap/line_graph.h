// Line(G) and the edge graph of the map (thesis Sec. 9.3, Fig. 9.7-9.10): the input of the regular
// surface stage.
//
// Line(G) holds one N O segment per element g (half of a map edge seen from one side of it); g and
// its partner g*S^-1*T (= g*T*S, the reflection in N0O0) are the same geometric segment. In the
// polygon of Tri(G) the two copies coincide except across the paired boundary; the identification
// of Sec. 9.3 moves the copies of every segment end onto one position. Its outcome is
// combinatorial: the copies of an N end are the vertex class g<S, T>, those of an O end the edge
// class g<T*S, R*T>. So the classes are taken from the group and each gets the position of its copy
// nearest the centre of the polygon, lifted to the Jemisphere (Fig. 9.9; for spherical maps the
// sphere itself, for torus maps the plane z = 0). The positions are only the starting geometry of
// the relaxation.
//
// The edge graph: nodes = map vertices (valence q), edges = map edges, and darts = vertex-edge
// incidences, one per orientation-preserving element g (the flag pair {g, g*T}), with the rotation
// system from S: the next dart counterclockwise around a node is g*S; the dart at the other end of
// the edge is g*R*S (the half turn about O).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "regmap/finite_group.h"
#include "regmap/triangle_tiling.h"

namespace tessera::regmap {

struct EdgeGraph {
  std::size_t node_count = 0;
  std::size_t edge_count = 0;
  std::vector<Element> dart_element;      // per dart: its orientation-preserving element
  std::vector<std::int32_t> dart_node;    // per dart
  std::vector<std::int32_t> dart_edge;    // per dart
  std::vector<std::int32_t> next_around;  // per dart: the next dart counterclockwise at its node
  std::vector<std::int32_t> opposite;     // per dart: the other dart of its edge
  std::vector<Vec3> node_position;        // per node
  std::vector<Vec3> edge_position;        // per edge: its midpoint
};

struct LineGraph {
  std::vector<Element> partner;       // per element: g*S^-1*T
  std::vector<std::int32_t> node_of;  // per element: the node at its N end
  std::vector<std::int32_t> edge_of;  // per element: the edge through its O end
  std::vector<std::int32_t> dart_of;  // per element: the dart of {g, g*T}
  EdgeGraph graph;
};

// Throws InputError for a non-orientable map (it has no rotation system).
LineGraph build_line_graph(const FiniteGroup& group, const TriangleTiling& tiling);

// The number of faces of the rotation system (orbits of next_around after opposite): F for a
// correctly built graph, so V - E + faces = 2 - 2g.
std::size_t rotation_system_faces(const EdgeGraph& graph);

}  // namespace tessera::regmap
