// Validation and repair of a mesh as read from a file or received from the page, so that every
// later stage can rely on a consistently oriented 2-manifold (possibly with boundary).
//
// In:  any Mesh.
// Out: the mesh repaired in place, and a report of what was repaired or is worth knowing:
//      - near-duplicate vertices on the boundary welded (closer than weld_tolerance x bounding-box
//        diagonal), except where welding would make the mesh non-manifold or non-orientable:
//        those are kept apart (a warning names one), so that any mesh valid without welding is
//        valid with it,
//      - faces with fewer than three distinct vertices dropped, repeated corners collapsed,
//      - vertices in no face removed,
//      - inconsistently oriented faces flipped (breadth-first from the majority orientation),
//      - zero-area faces counted (kept: dropping them would open holes),
//      - several connected components counted.
// Throws TopologyError (no faces, indices out of range, non-manifold edges or vertices,
// non-orientable surfaces) and GeometryError (NaN/Inf coordinates, only zero-area faces), each
// naming the vertex, edge or face and what the user can do.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace tessera {

struct ValidationOptions {
  // Relative to the bounding-box diagonal; 0 welds bit-identical positions only; negative: no
  // welding.
  double weld_tolerance = 1e-7;
  // Faces with area below this times the squared bounding-box diagonal count as zero-area.
  double zero_area_tolerance = 1e-14;
};

struct ValidationReport {
  std::size_t welded_vertices = 0;        // merged into another vertex
  std::size_t unwelded_groups = 0;        // near-duplicates kept apart: welding breaks the surface
  std::size_t unreferenced_vertices = 0;  // in no face, removed
  std::size_t dropped_faces = 0;          // fewer than three distinct vertices
  std::size_t collapsed_faces = 0;        // repeated consecutive corners merged
  std::size_t zero_area_faces = 0;        // kept
  std::size_t flipped_faces = 0;          // re-oriented to agree with their neighbours
  std::size_t components = 0;
  std::vector<std::string> warnings;  // one sentence per finding, for people

  // Whether the faces as given were consistently oriented.
  bool oriented_as_given() const { return flipped_faces == 0; }
};

ValidationReport validate_mesh(Mesh& mesh, const ValidationOptions& options = {});

}  // namespace tessera
