#include "layout/layout_scene.h"

#include <cmath>
#include <map>
#include <string>

namespace tessera::layout {
namespace {

Color hsv(double hue, double saturation, double value) {
  const double h = 6 * (hue - std::floor(hue));
  const int sector = int(h) % 6;
  const double f = h - std::floor(h);
  const float v = float(value), p = float(value * (1 - saturation)),
              q = float(value * (1 - saturation * f)),
              t = float(value * (1 - saturation * (1 - f)));
  switch (sector) {
    case 0:
      return {v, t, p};
    case 1:
      return {q, v, p};
    case 2:
      return {p, v, t};
    case 3:
      return {p, q, v};
    case 4:
      return {t, p, v};
    default:
      return {v, p, q};
  }
}

Color valence_color(int valence) {
  switch (valence) {
    case 3:
      return {0.1f, 0.3f, 0.9f};
    case 5:
      return {0.9f, 0.15f, 0.1f};
    default:
      return {0.6f, 0.1f, 0.7f};
  }
}

}  // namespace

Color patch_color(std::int32_t patch) {
  const double hue = 0.61803398875 * double(patch);
  return hsv(hue, patch % 2 ? 0.45 : 0.6, patch % 3 == 2 ? 0.8 : 0.95);
}

Scene layout_scene(const Charts& charts, const LayoutGraph& graph, const QuadLayout& layout) {
  Scene scene;
  scene.mesh = layout.refined.mesh;
  for (std::int32_t p : scene.mesh.face_attributes.at("patch"))
    scene.face_colors.push_back(patch_color(p));
  LineSet arcs{"arcs", {}, Color(0.05f, 0.05f, 0.05f)};
  for (const Arc& arc : layout.arcs)
    arcs.polylines.push_back(arc_polyline(charts.mesh, charts.connectivity, arc));
  scene.line_sets.push_back(std::move(arcs));
  std::map<int, PointSet> by_valence;
  for (const SingularPoint& point : graph.graph.ports.points) {
    PointSet& set = by_valence[point.valence];
    set.name = "singularities valence " + std::to_string(point.valence);
    set.color = valence_color(point.valence);
    set.points.push_back(charts.mesh.positions[point.ring.vertex]);
  }
  for (auto& [valence, set] : by_valence) scene.point_sets.push_back(std::move(set));
  scene.extras = nlohmann::json::parse(layout_json(graph, layout).dump());
  return scene;
}

}  // namespace tessera::layout
