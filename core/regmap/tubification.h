// Tubification of an embedded edge graph into its regular surface (thesis Sec. 9.2, 9.4 and
// Fig. 9.11, 9.14): tubes for the edges, junctions for the nodes, holes for the faces.
//
// The surface is tiled by quarter tubes Q_g, one per group element g (4E of them): the part of
// the tube of g's half edge (its N O segment in Line(G)) between node and midpoint, on the side
// facing g's face M. An orientation-preserving g has its face on the left of its dart (seen along
// the dart with the junction normal up), so Q_g is folded left and Q_{g S^-1 T} right; the two
// form the half tube (Sec. 9.4). Each Q_g is a grid of quads with four sides, named as in
// Sec. 9.5 (Fig. 9.15):
//   a  at the junction, from the top pole over the gap between two darts to the bottom pole,
//      shared with Q_{gT} (the neighbouring dart's quarter tube facing the same hole);
//   b  the top seam along the tube, shared with Q_{g S^-1 T};
//   c  the half ring at the edge midpoint, shared with Q_{gRT} (the other half of the edge);
//   d  the bottom seam, shared with Q_{g S^-1 T} again.
// The junction is a rounded plate of thickness 2 r: over the node's tangent plane the darts' strips
// of half-width r are joined by fillets of radius `roundness * r`, so q tubes meet without
// overlapping for every q >= 3 (the fillets end where the tubes begin, at the reach
// (r + fillet) / tan(pi / q)). Along an edge the tube follows a C1 chain of cubic Bezier arcs
// through the edge's waypoints, leaving each junction along its dart, with a rotation-minimizing
// frame whose twist is spread so that the seams meet both junctions' normals.
//
// In:  an embedded edge graph with its Line(G) and junction order, a tube shape.
// Out: one closed, consistently oriented quad mesh (outward normals) with the face attribute
//      "tile" (the quarter tube: its group element).
#pragma once

#include "mesh/mesh.h"
#include "regmap/embedded_graph.h"

namespace tessera::regmap {

inline constexpr const char* kTileAttribute = "tile";

struct TubeOptions {
  double radius = 0.0;     // in units of a tube's length (node to midpoint); 0: automatic
  double roundness = 1.0;  // fillet radius between neighbouring tubes, in tube radii
  int smoothness = 4;      // quads across a quarter tube (top seam to bottom seam)
};

struct TubeShape {
  double radius = 0.0;
  double fillet = 0.0;
  double reach = 0.0;         // from the node to where a tube begins
  double arm = 0.0;           // a tube's first stretch along its dart, before it bends
  double clearance = 0.0;     // the distance two tubes' centrelines should keep
  int across = 0;             // quads from seam to seam
  int along = 0;              // quads from the junction's end to the midpoint, at least
  double ring_spacing = 0.0;  // longer tubes get more quads along, at most this far apart
  int junction = 0;           // quads from the node to the junction's end
};

// The automatic radius is 0.15, smaller for q > 6 so that the junction keeps the same reach.
// Throws InputError for q < 3 (two tubes do not make a junction), a radius or roundness that is
// not positive and finite, or a smoothness outside 2..32.
TubeShape tube_shape(const TubeOptions& options, int valence);

// The quad grid of one quarter tube: vertex (i, j) is vertex[i * (across + 1) + j], i from side a
// at the junction (0) to side c at the edge's midpoint (columns), j from the top seam b (0) to the
// bottom seam d (across). Its quads run counterclockwise seen from outside in the (i, j) plane
// when `counterclockwise` (the quarter tube left of its dart), clockwise otherwise. Neighbouring
// quarter tubes share the vertices of their common side at the same i (seams) or j (sides a, c).
struct QuarterTubeGrid {
  int columns = 0;
  int across = 0;
  bool counterclockwise = true;
  std::vector<Index> vertex;
  Index at(int i, int j) const { return vertex[static_cast<std::size_t>(i * (across + 1) + j)]; }
};

struct TubifiedSurface {
  Mesh mesh;
  std::vector<QuarterTubeGrid> grids;  // per tile: its group element
};

// Faces: 4 * across * (junction + along_e) quads per edge e, where along_e >= along grows with the
// length of e's tube. Throws LimitError when they are more than max_faces.
TubifiedSurface tubify(const EmbeddedGraph& embedded, const LineGraph& line,
                       const JunctionOrder& order, const TubeShape& shape, std::size_t max_faces);

}  // namespace tessera::regmap
