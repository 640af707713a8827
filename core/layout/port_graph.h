// The graph of the ports G (thesis Ch. 4, Sec. 6.7-6.8) as a value: the open separatrices grown
// from every port, the count of the intersection points K met, the edges of G (closed separatrices
// between two ports, or a port and a virtual port on the boundary, Sec. 4.4), and the conflict
// pairs I (Sec. 4.6, with the zero-area pairs Z of Remark 4.2).
//
// An edge keeps its base and height lengths, so that its weight w = L_base + alpha * L_height (4.1)
// is recomputed for any alpha without tracing again.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "layout/ports.h"

namespace tessera::layout {

enum class LineEnd : std::uint8_t {
  growing,       // still being traced
  length_limit,  // reached L_max (Sec. 6.8)
  spiral,        // stopped by the spiral test (6.7), (6.8)
  boundary,      // left the surface (a virtual port, Sec. 4.4)
  singularity,   // ran into a singularity: a closed separatrix
};

const char* to_string(LineEnd end);

// The part of a separatrix inside one face, in that face's chart.
struct SeparatrixPiece {
  Index line = 0;
  Index face = 0;
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // the line's (axis-parallel) direction
  double start = 0;                                     // L at `from`
  double length = 0;
};

// The open separatrix gamma_a+ of a port (Def. 2.5); separatrix i belongs to port i.
struct Separatrix {
  double length = 0;                                      // traced
  double stop = std::numeric_limits<double>::infinity();  // where the spiral test stopped it
  LineEnd end = LineEnd::growing;
  Index end_vertex = kNoIndex;  // the singularity it ran into
  std::vector<Index> pieces;    // in order along the line
  std::size_t steps = 0;        // faces entered
};

// An intersection point m of two open separatrices (a and b may be one self-crossing line; then
// length_a < length_b), in the chart of `face`.
struct Crossing {
  Index line_a = 0;
  Index line_b = 0;
  double length_a = 0;  // L_a(m)
  double length_b = 0;  // L_b(m)
  Index face = 0;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction_a = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction_b = Eigen::Vector2d::Zero();
  double time() const { return std::max(length_a, length_b); }
};

enum class EdgeKind : std::uint8_t {
  crossing,     // condition C1 at a crossing: the hypotenuse of base and height
  singularity,  // a separatrix that ran into a singularity (height: how far it passed it)
  boundary,     // a separatrix that ran into the boundary, to its virtual port (height 0)
};

struct GraphEdge {
  EdgeKind kind = EdgeKind::crossing;
  Index u = 0;  // node of the base port
  Index v = 0;  // node of the other port, or of a virtual port
  Index base_line = 0;
  Index height_line = kNoIndex;  // kind == crossing only
  double base = 0;               // L_base >= L_height
  double height = 0;
  // +1 if the height line runs along +J d_base at the crossing (the far singularity lies on the
  // right of the base line), -1 if along -J d_base.
  int side = 1;
  bool diagonal = false;  // case 3 of C1 (L_a = L_b): one of a zero-area pair
};

// The edge condition C1 makes at a crossing (Sec. 4.1): from the port of the base line to the port
// `far` next to the height line's at its singularity.
inline GraphEdge crossing_edge(Index base_line, Index far, Index height_line, double base,
                               double height, int side) {
  GraphEdge edge;
  edge.kind = EdgeKind::crossing;
  edge.u = base_line;
  edge.v = far;
  edge.base_line = base_line;
  edge.height_line = height_line;
  edge.base = base;
  edge.height = height;
  edge.side = side;
  return edge;
}

// A virtual port (Sec. 4.4): where a separatrix leaves the surface.
struct VirtualPort {
  Index line = 0;
  double length = 0;
  Index face = 0;  // the last face, and the exit point in its chart
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

struct EdgePair {
  Index first = 0;  // edge indices, first < second
  Index second = 0;
  auto operator<=>(const EdgePair&) const = default;
};

struct PortGraph {
  Ports ports;
  std::vector<Separatrix> separatrices;  // one per port
  std::vector<SeparatrixPiece> pieces;
  // Intersections of two separatrices (or of one with itself) reached while growing, whether
  // or not C1 made edges of them.
  std::size_t crossing_count = 0;
  std::vector<GraphEdge> edges;
  std::vector<VirtualPort> virtual_ports;  // node ports.ports.size() + i
  std::vector<EdgePair> zero_area;         // Z (Remark 4.2)
  std::vector<EdgePair> conflicts;         // I, including Z (Algorithm 1)
  double length_limit = 0;                 // L_max the separatrices were grown to

  std::size_t port_count() const { return ports.ports.size(); }
  std::size_t node_count() const { return port_count() + virtual_ports.size(); }
  bool is_virtual(Index node) const { return node >= port_count(); }
};

// (4.1): w_e = L_base + alpha * L_height.
inline double edge_weight(const GraphEdge& edge, double alpha) {
  return edge.base + alpha * edge.height;
}

}  // namespace tessera::layout
