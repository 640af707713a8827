// A map drawn on its target's surface, from the realization to what leaves Tessera: the one flow
// (and JSON, and GLB scene) that `tessera regmap map` and the page's worker share.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/limits.h"
#include "base/progress.h"
#include "export/scene.h"
#include "regmap/mapped_map.h"
#include "regmap/realization.h"
#include "regmap/regular_surface.h"

namespace tessera::regmap {

struct DrawnMap {
  Realization realization;
  SurfaceStats surface;  // the target surface's
  MappedMap drawn;
};

// Builds the target's regular surface (its self-intersections not searched: the drawing's are)
// and draws M on it through the realization's pairing.
DrawnMap draw_realization(const FiniteGroup& source, const ElementWords& words,
                          const Realization& realization, const MappedMapOptions& options,
                          const Limits& limits, const Progress& progress = Progress());

// Draws the realizations of `search`, those on surfaces free of self-intersections first and each
// kind in ranked order, until one draws M right (drawn_right), and moves it to the front; those
// drawn before it wrong (or that did not glue) are removed and counted in search.drawn_wrong.
// Nothing when none draws right (`found` then holds none that was drawn wrong).
std::optional<DrawnMap> draw_first_right(RealizationSearch& search, const FiniteGroup& source,
                                         const ElementWords& words, const MapFigures& figures,
                                         const MappedMapOptions& options, TargetSurfaces& surfaces,
                                         TargetGroups& groups,
                                         const Progress& progress = Progress());

// M (named `name`) drawn on the best target that draws it right: the one named `on` (it must have
// M's genus) or, when `on` is empty, every catalog target of M's genus, searched and drawn by
// draw_first_right. InputError naming the targets tried when none does. `others`, when given,
// gets the other targets found to draw it right.
DrawnMap draw_on_best_target(const FiniteGroup& source, const ElementWords& words,
                             const MapFigures& figures, const std::string& name,
                             const Catalog& catalog, const std::string& on,
                             const PairingLimits& pairing_limits, const MappedMapOptions& options,
                             const Limits& limits, const Progress& progress,
                             std::vector<std::string>* others = nullptr);

// source, target, target_kind, genus, V, E, F (found), expected {V, E, F}, face_orbits (of M's
// faces under the surface's rotations), faces_are_disks,
// covers_once, closed, oriented, self_intersections (null when not searched),
// symmetries_verified, surface_base, subdivisions, mesh_vertices, mesh_faces, pairing, seconds.
nlohmann::ordered_json drawn_map_json(const std::string& source_name, const MapFigures& figures,
                                      const DrawnMap& map, double seconds);

// The drawing with faces coloured by M's face, per-face "face", "orbit" and "tile" (_FACE, _ORBIT,
// _TILE in GLB),
// M's edges as the line set "edges", extras {"map": name, "mapped": drawn_map_json(...)}.
Scene drawn_map_scene(const DrawnMap& map, const std::string& source_name,
                      const nlohmann::ordered_json& figures);

}  // namespace tessera::regmap
