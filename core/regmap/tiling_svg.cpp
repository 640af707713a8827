#include "regmap/tiling_svg.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "export/svg.h"

namespace tessera::regmap {

using enum Letter;

namespace {

constexpr double kGoldenRatio = 0.6180339887498949;
constexpr double kHemisphereGap = 2.15;  // x offset of the back hemisphere's centre

struct Extent {
  double min_x, min_y, max_x, max_y;
};

// Where the drawing puts the tiling's points.
class Projection {
 public:
  explicit Projection(const TriangleTiling& tiling) : tiling_(tiling) {}

  Extent extent() const {
    switch (tiling_.geometry()) {
      case Geometry::Hyperbolic:
        return {-1.03, -1.03, 1.03, 1.03};
      case Geometry::Spherical:
        return {-1.05, -1.05, kHemisphereGap + 1.05, 1.05};
      case Geometry::Euclidean:
        break;
    }
    Extent e{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
             std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
    for (const auto& corners : tiling_.corners) {
      for (const Point& p : corners) {
        const Complex z = to_plane(p);
        e = {std::min(e.min_x, z.real()), std::min(e.min_y, z.imag()), std::max(e.max_x, z.real()),
             std::max(e.max_y, z.imag())};
      }
    }
    const double margin = 0.03 * std::max(e.max_x - e.min_x, e.max_y - e.min_y);
    return {e.min_x - margin, e.min_y - margin, e.max_x + margin, e.max_y + margin};
  }

  // The views a triangle shows in: the plane models have one; on the sphere, the front and/or the
  // back hemisphere, whichever holds one of its corners (a great-circle arc between two points of
  // one open hemisphere stays in it).
  std::vector<bool> views(std::size_t g) const {
    if (tiling_.geometry() != Geometry::Spherical) return {false};
    double lowest = 1, highest = -1;
    for (const Point& p : tiling_.corners[g]) {
      const double z = to_sphere(p).z;
      lowest = std::min(lowest, z);
      highest = std::max(highest, z);
    }
    std::vector<bool> result;
    if (highest > -1e-12) result.push_back(false);
    if (lowest < 1e-12) result.push_back(true);
    return result;
  }

  // Orthographic views of the two hemispheres, the back one seen from behind; points beyond a
  // view's horizon are pushed onto its rim, so a triangle across the equator is cut there.
  SvgPoint operator()(const Point& p, bool back) const {
    if (tiling_.geometry() != Geometry::Spherical) {
      const Complex z = to_plane(p);
      return {z.real(), z.imag()};
    }
    Vec3 v = to_sphere(p);
    if (back) v = {-v.x, v.y, -v.z};
    if (v.z < 0) {
      const double r = std::hypot(v.x, v.y);
      v = {v.x / r, v.y / r, 0};
    }
    return {v.x + (back ? kHemisphereGap : 0.0), v.y};
  }

 private:
  const TriangleTiling& tiling_;
};

double chord(SvgPoint a, SvgPoint b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

class TilingPicture {
 public:
  TilingPicture(const FiniteGroup& group, const TriangleTiling& tiling, double width_px)
      : tiling_(tiling),
        project_(tiling),
        extent_(project_.extent()),
        pixels_per_unit_(width_px / (extent_.max_x - extent_.min_x)),
        svg_(extent_.min_x, extent_.min_y, extent_.max_x, extent_.max_y, width_px),
        faces_(face_orbits(group)),
        orientation_(orbits(group, {{R}, {S}})) {}

  std::string draw(const std::string& title) {
    svg_.title(title);
    draw_frame();
    for (std::size_t g = 0; g < tiling_.size(); ++g) draw_triangle(g);
    for (std::size_t g = 0; g < tiling_.size(); ++g) draw_map_edge(g);
    for (std::size_t k = 0; k < tiling_.pairs.size(); ++k) draw_pair(k);
    return svg_.str();
  }

 private:
  void draw_frame() {
    const SvgStyle frame{"none", "#888888", 1.0};
    if (tiling_.geometry() == Geometry::Hyperbolic) svg_.circle({0, 0}, 1.0, frame);
    if (tiling_.geometry() == Geometry::Spherical) {
      svg_.circle({0, 0}, 1.0, frame);
      svg_.circle({kHemisphereGap, 0}, 1.0, frame);
    }
  }

  // The side from corner a to corner b of triangle g, sampled along the geodesic finely enough
  // to look curved where it is large.
  std::vector<SvgPoint> side(std::size_t g, Corner a, Corner b, bool back) const {
    const Point& pa = tiling_.corners[g][a];
    const Point& pb = tiling_.corners[g][b];
    const double length_px = chord(project_(pa, back), project_(pb, back)) * pixels_per_unit_;
    const int steps = std::clamp(static_cast<int>(length_px / 6), 1, 24);
    std::vector<SvgPoint> points;
    for (int i = 0; i <= steps; ++i)
      points.push_back(
          project_(geodesic_point(tiling_.geometry(), pa, pb, double(i) / steps), back));
    return points;
  }

  std::string triangle_colour(std::size_t g) const {
    const double hue = faces_.label[g] * kGoldenRatio;
    return hsl_colour(hue, 0.55, orientation_.label[g] == 0 ? 0.62 : 0.72);
  }

  void draw_triangle(std::size_t g) {
    const std::string colour = triangle_colour(g);
    for (const bool back : project_.views(g)) {
      std::vector<SvgPoint> outline;
      for (const auto& [a, b] : {std::pair{kM, kN}, {kN, kO}, {kO, kM}}) {
        std::vector<SvgPoint> s = side(g, a, b, back);
        outline.insert(outline.end(), s.begin(), s.end() - 1);
      }
      svg_.polygon(outline, {colour, colour, 0.3});
    }
  }

  // Line width that shrinks with the triangles towards the rim of the disk.
  double width_for(const std::vector<SvgPoint>& line, double widest) const {
    const double length_px = chord(line.front(), line.back()) * pixels_per_unit_;
    return std::clamp(length_px / 25, 0.1, widest);
  }

  void draw_map_edge(std::size_t g) {
    for (const bool back : project_.views(g)) {
      const std::vector<SvgPoint> edge = side(g, kN, kO, back);
      svg_.polyline(edge, {"none", "#303030", width_for(edge, 1.2)});
    }
  }

  void draw_pair(std::size_t k) {
    const BoundaryPair& pair = tiling_.pairs[k];
    const std::string colour = hsl_colour(k * kGoldenRatio, 0.85, 0.42);
    for (Element e : {pair.first, pair.second}) {
      const auto g = static_cast<std::size_t>(e);
      const auto [from, to] = side_corners(pair.side);
      for (const bool back : project_.views(g)) {
        const std::vector<SvgPoint> line = side(g, from, to, back);
        svg_.polyline(line, {"none", colour, width_for(line, 3.0)});
        draw_arrow_and_number(line, k + 1, colour);
      }
    }
  }

  // An arrowhead at the middle of the side pointing from its first to its last point, and the
  // pair's number beside it, both sized to the side.
  void draw_arrow_and_number(const std::vector<SvgPoint>& line, std::size_t number,
                             const std::string& colour) {
    const SvgPoint a = line.front(), b = line.back();
    const double length = chord(a, b);
    if (length * pixels_per_unit_ < 4) return;
    const double ux = (b.x - a.x) / length, uy = (b.y - a.y) / length;
    const SvgPoint mid = line[line.size() / 2];
    const double h = std::min(0.18 * length, 9 / pixels_per_unit_);
    svg_.polygon({{mid.x + ux * h, mid.y + uy * h},
                  {mid.x - ux * h - uy * h * 0.6, mid.y - uy * h + ux * h * 0.6},
                  {mid.x - ux * h + uy * h * 0.6, mid.y - uy * h - ux * h * 0.6}},
                 {colour, "none", 0});
    const double size_px = std::min(14.0, length * pixels_per_unit_ / 3);
    if (size_px < 5) return;
    const double offset = 1.6 * h;
    svg_.text({mid.x - uy * offset, mid.y + ux * offset}, std::to_string(number), size_px, colour);
  }

  const TriangleTiling& tiling_;
  Projection project_;
  Extent extent_;
  double pixels_per_unit_;
  SvgDocument svg_;
  Orbits faces_;
  Orbits orientation_;
};

}  // namespace

std::string tiling_svg(const FiniteGroup& group, const TriangleTiling& tiling,
                       const std::string& title, double width_px) {
  return TilingPicture(group, tiling, width_px).draw(title);
}

}  // namespace tessera::regmap
