// A source map M drawn on the regular surface of a target map T (thesis Sec. 9.5-9.6, Fig. 9.17).
//
// A pairing (pairing.h) gives the fundamental quadrilateral hQ in M's universal cover, made of k
// flag triangles of M, and the images a', b', c' in Sym(M) of the reflections in the quarter
// tube's sides. The surface's quarter tubes are structured grids (tubification.h), and their
// adjacency is read off the mesh (surface_group.h). The drawing:
//   1. the template: hQ's flag triangles, each subdivided n x n in the Klein model (where M's
//      geodesics are straight), welded into one triangulated disk; every template vertex gets
//      coordinates (s, t) in the unit square by inverting the bilinear map of hQ's Klein corners
//      P1 (0,0), P2 (1,0), P3 (1,1), P4 (0,1), so that the sides L4 (junction), L1 (top seam),
//      L2 (midpoint), L3 (bottom seam) land on s = 0, t = 0, s = 1, t = 1;
//   2. the group: phi(tile) in Sym(M) for every quarter tube by a walk over the mesh's adjacency,
//      phi(across the junction) = phi c', phi(across a seam) = phi a', phi(across the midpoint) =
//      phi b', checked on every adjacency (the pairing glues) and for injectivity;
//   3. the mesh: the template in every quarter tube g at the grid's point (s columns, t across),
//      triangles of flag f labelled with M's face of phi(g) f, vertices on a side shared with the
//      neighbour across it; M's edges are the template's edges along N-O sides.
// Checks, all from the built mesh: closed, oriented, genus, the images {phi(g) f} cover Sym(M)
// once, F distinct face labels each a topological disk, V map vertices, E edge midpoints, and
// (optionally) no self-intersections.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "base/progress.h"
#include "mesh/mesh.h"
#include "regmap/element_words.h"
#include "regmap/pairing.h"
#include "regmap/regular_surface.h"

namespace tessera::regmap {

inline constexpr const char* kFaceAttribute = "face";

struct MappedMapOptions {
  int subdivisions = 0;  // per flag triangle side; 0 picks it from the quarter tube's grid
  bool find_self_intersections = true;
};

struct MappedMapStats {
  std::size_t vertices = 0;  // M's vertices found on the surface
  std::size_t edges = 0;     // M's edges (their midpoints) found
  std::size_t faces = 0;     // distinct face labels
  bool faces_are_disks = false;
  bool covers_once = false;  // every flag of M in exactly one quarter tube
  bool closed = false;
  bool oriented = false;
  long genus = 0;
  std::size_t self_intersections = 0;
  bool self_intersections_searched = false;
  int subdivisions = 0;
  std::size_t mesh_vertices = 0;
  std::size_t mesh_faces = 0;
};

struct MappedMap {
  Mesh mesh;  // face attributes "face" (M's face) and "tile" (the quarter tube)
  std::vector<std::array<Index, 2>> edge_segments;  // M's edges, as mesh edges
  MappedMapStats stats;
};

// Throws Error when the pairing does not glue on the surface's quarter tubes (the pairing and
// the surface do not belong together).
MappedMap map_onto_surface(const FiniteGroup& source, const ElementWords& words,
                           const Pairing& pairing, const RegularSurface& surface,
                           const MappedMapOptions& options = {},
                           const Progress& progress = Progress());

}  // namespace tessera::regmap
