// A source map M drawn on the regular surface of a target map T (thesis Sec. 9.5-9.6, Fig. 9.17).
//
// A pairing (pairing.h) gives two geodesic quadrilaterals in M's universal cover, Q (quarter tube
// 0) and c Q (its mirror image across the junction side), and the images x, y in Sym+(M) of the
// rotations S and R S of Sym+(T). The surface's quarter tubes are structured grids
// (tubification.h), and their adjacency is read off the mesh (surface_group.h). The drawing:
//   1. two templates, one per quadrilateral: M's triangles that meet it, clipped to it in the
//      Klein model (where geodesics are straight), fanned and subdivided, welded into one
//      triangulated disk; its sides at their arc-length parameters on the unit square's sides
//      (L1 t = 0 from P1, L2 s = 1 from P2, L3 t = 1 from P4, L4 s = 0 from P1), the rest by
//      Floater's mean-value map (no folds), then laid over the quarter tube's grid: every
//      template triangle clipped to every grid triangle it meets (the surface's quads fanned
//      from their (i, j) corner), the convex pieces fanned, so that every triangle of the drawing
//      lies in one triangle of the surface and one flag of M;
//   2. the group: each quarter tube carries g Q or g c Q, by a walk over the mesh's adjacency
//      (across the junction the same g, across a seam g x^-1 and back g x, across the midpoint
//      g y x^-1 and back), checked on every adjacency and for injectivity;
//   3. the mesh: the overlay in every quarter tube, each vertex in the plane of its surface
//      triangle (the drawing is a subdivision of the surface: it self-intersects only where the
//      surface does), triangles labelled with M's face of g times their flag and with that face's
//      orbit under the elements the quarter tubes of one kind carry (the image of Sym+(T): the
//      rotations of the surface that carry the drawing onto itself), side vertices shared with the
//      neighbour's (both templates cut a side alike: the pairing's rotations map one onto the
//      other); M's edges are the template's edges along N-O sides.
// Checks, all from the built mesh: closed, oriented, genus, the pieces' areas cover every flag
// of M once, F distinct face labels each an open disk, V map vertices, E edge midpoints, and
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
inline constexpr const char* kOrbitAttribute = "orbit";

struct MappedMapOptions {
  int subdivisions = 0;  // of the template's pieces before the overlay; 0 picks 2
  bool find_self_intersections = true;
};

struct MappedMapStats {
  std::size_t vertices = 0;     // M's vertices found on the surface
  std::size_t edges = 0;        // M's edges (their midpoints) found
  std::size_t faces = 0;        // distinct face labels
  std::size_t face_orbits = 0;  // orbits of M's faces under the surface's rotations
  bool faces_are_disks = false;
  bool covers_once = false;  // the quarter tubes cover every flag of M once (by area)
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
  Mesh mesh;  // face attributes "face" (M's face), "orbit" (its orbit), "tile" (the quarter tube)
  std::vector<std::array<Index, 2>> edge_segments;  // M's edges, as mesh edges
  MappedMapStats stats;
};

// Whether the drawing is M as its group says: V, E, F found, faces open disks, every flag covered
// once, the surface closed, oriented and of M's genus.
bool drawn_right(const MappedMapStats& stats, const MapFigures& figures);

// Throws Error when the pairing does not glue on the surface's quarter tubes (the pairing and
// the surface do not belong together).
MappedMap map_onto_surface(const FiniteGroup& source, const ElementWords& words,
                           const Pairing& pairing, const RegularSurface& surface,
                           const MappedMapOptions& options = {},
                           const Progress& progress = Progress());

}  // namespace tessera::regmap
