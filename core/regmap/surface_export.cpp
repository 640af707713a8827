#include "regmap/surface_export.h"

#include <cmath>

namespace tessera::regmap {

nlohmann::ordered_json surface_stats_json(const SurfaceStats& s) {
  const RelaxReport& r = s.relaxation;
  using Json = nlohmann::ordered_json;
  return {{"genus", s.genus},
          {"euler_characteristic", s.euler_characteristic},
          {"quarter_tubes", s.quarter_tubes},
          {"closed", s.closed},
          {"oriented", s.oriented},
          {"self_intersections",
           s.self_intersections_searched ? Json(s.self_intersections) : Json(nullptr)},
          {"relations_hold", s.relations_hold},
          {"seconds", s.seconds},
          {"failed_relations", s.failed_relations},
          {"base", s.base},
          {"symmetries", s.symmetries},
          {"symmetries_verified", s.symmetries_verified},
          {"junctions", s.junctions},
          {"tubes", s.tubes},
          {"vertices", s.vertices},
          {"faces", s.faces},
          {"tube_radius", s.tube_radius},
          {"relaxation",
           {{"iterations", r.iterations},
            {"energy", r.energy},
            {"energy_change", r.energy_change},
            {"rms_motion", r.rms_motion},
            {"max_dart_angle", r.max_dart_angle},
            {"overlaps", r.overlaps}}}};
}

Color quarter_tube_color(std::int32_t tile) {
  constexpr double kGoldenTurn = 0.6180339887498949;
  const double hue = std::fmod(0.13 + kGoldenTurn * tile, 1.0) * 6.0;
  const double x = 1.0 - std::abs(std::fmod(hue, 2.0) - 1.0);
  constexpr double kLow = 0.25;  // pastel: no channel below this
  const double rgb[6][3] = {{1, x, 0}, {x, 1, 0}, {0, 1, x}, {0, x, 1}, {x, 0, 1}, {1, 0, x}};
  const auto* c = rgb[static_cast<int>(hue) % 6];
  return {static_cast<float>(kLow + (1 - kLow) * c[0]),
          static_cast<float>(kLow + (1 - kLow) * c[1]),
          static_cast<float>(kLow + (1 - kLow) * c[2])};
}

Scene regular_surface_scene(const RegularSurface& surface, const std::string& map_name) {
  Scene scene;
  scene.mesh = surface.mesh;
  for (std::int32_t tile : surface.mesh.face_attributes.at(kTileAttribute))
    scene.face_colors.push_back(quarter_tube_color(tile));
  scene.extras = {{"map", map_name}, {"surface", surface_stats_json(surface.stats)}};
  return scene;
}

}  // namespace tessera::regmap
