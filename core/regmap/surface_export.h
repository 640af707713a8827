// What a regular surface carries out of Tessera: its figures as JSON (one definition shared by
// `tessera regmap surface --json` and the wasm module) and a Scene for GLB with the quarter tubes
// coloured, the per-face "tile" attribute (written as "_TILE") and the figures in extras.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "export/scene.h"
#include "regmap/regular_surface.h"

namespace tessera::regmap {

// In this order: genus, euler_characteristic, quarter_tubes, closed, oriented, self_intersections
// (null when not searched), relations_hold, seconds, failed_relations, base, symmetries,
// symmetries_verified, junctions, tubes,
// vertices, faces, tube_radius, relaxation {iterations, energy, energy_change, rms_motion,
// max_dart_angle}.
nlohmann::ordered_json surface_stats_json(const SurfaceStats& stats);

// A colour per quarter tube: hues spread by the golden angle over the tile numbers.
Color quarter_tube_color(std::int32_t tile);

// The surface's mesh with face colours by quarter tube; extras hold {"map": name, "surface":
// surface_stats_json(...)}.
Scene regular_surface_scene(const RegularSurface& surface, const std::string& map_name);

}  // namespace tessera::regmap
