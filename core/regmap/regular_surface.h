// The regular surface of a map by targetless tubification (thesis Sec. 9.2-9.5): the map's edge
// graph (Line(G) identified, Sec. 9.3) placed in space, either on a symmetric base (a double cover
// of a Platonic solid, or one or two junctions: symmetric_base.h) or by the constrained relaxation
// from the Jemisphere (relaxation.h) — and, when the relaxed surface crosses itself, on the spine
// (spine_base.h) if that crosses itself less — tubified (tubification.h), and checked: closed,
// oriented, genus E - V + 1, 4E quarter tubes, the relations of A, B, C on the mesh
// (surface_group.h), self-intersections, and the base's rotations on the mesh's vertices
// (mesh/symmetry.h).
//
// In:  the map's presentation (for its relators) and its enumerated group.
// Out: the mesh (face attribute "tile") and its figures as plain values.
// Throws InputError for a non-orientable map, a junction valence below 3, bad tube options, or
//      --base platonic for a map without a symmetric base; LimitError when the surface would have
//      more faces than limits.max_faces (or the tiling more triangles than its limit);
//      CancelledError through `progress`.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "base/limits.h"
#include "base/progress.h"
#include "mesh/mesh.h"
#include "regmap/finite_group.h"
#include "regmap/presentation.h"
#include "regmap/relaxation.h"
#include "regmap/surface_group.h"
#include "regmap/tubification.h"

namespace tessera::regmap {

enum class SurfaceBase {
  Automatic,  // the symmetric base when the map has one, else the relaxation (or the spine)
  Platonic,   // the symmetric base (symmetric_base.h), or an InputError
  Relax,      // the relaxation from the Jemisphere
};

struct SurfaceOptions {
  SurfaceBase base = SurfaceBase::Automatic;
  TubeOptions tube;
  RelaxOptions relax;
  bool find_self_intersections = true;
};

struct SurfaceStats {
  std::string base;            // "relaxation" or the symmetric base's name ("2-Octahedron", ...)
  std::size_t symmetries = 0;  // rotations the symmetric base has (0 for the relaxation)
  std::size_t symmetries_verified = 0;  // of those, the ones that map the mesh's vertices onto
                                        // themselves
  std::size_t junctions = 0;            // V of the edge graph
  std::size_t tubes = 0;                // E
  std::size_t vertices = 0;             // of the mesh
  std::size_t faces = 0;
  long euler_characteristic = 0;
  long genus = 0;
  std::size_t components = 0;
  bool closed = false;
  bool oriented = false;
  std::size_t quarter_tubes = 0;  // distinct tiles on the mesh
  bool relations_hold = false;
  std::size_t relations_checked = 0;
  std::vector<std::string> failed_relations;
  std::size_t self_intersections = 0;  // intersecting triangle pairs; 0 when not searched
  bool self_intersections_searched = false;
  double tube_radius = 0.0;
  RelaxReport relaxation;  // iterations 0 on a symmetric base
  double seconds = 0.0;    // placement, tubification and checks (not the enumeration)
};

struct RegularSurface {
  Mesh mesh;
  std::vector<QuarterTubeGrid> grids;  // per quarter tube (group element): its quad grid
  SurfaceGroup group;                  // A, B, C read off the mesh
  SurfaceStats stats;
};

RegularSurface build_regular_surface(const Presentation& presentation, const FiniteGroup& group,
                                     const SurfaceOptions& options = {},
                                     const Limits& limits = Limits(),
                                     const Progress& progress = Progress());

}  // namespace tessera::regmap
