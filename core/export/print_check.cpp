#include "export/print_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>

#include "base/error.h"
#include "mesh/edge_table.h"
#include "mesh/geometry.h"
#include "mesh/self_intersection.h"
#include "mesh/triangle_grid.h"

namespace tessera {
namespace {

// The largest print size taken (10 m): beyond it a size is a typing error.
constexpr double kLargestPrintMm = 10'000.0;

std::string millimetres(double x) {
  std::ostringstream out;
  out.precision(x < 10 ? 2 : 3);
  out << x << " mm";
  return out.str();
}

void check_options(const PrintOptions& options) {
  if (!(options.size_mm > 0 && options.size_mm <= kLargestPrintMm))
    throw InputError("the print size must be a length in millimetres above 0 and at most " +
                     millimetres(kLargestPrintMm));
  if (!(options.wall_mm > 0 && options.wall_mm < options.size_mm))
    throw InputError(
        "the wall thickness must be a length in millimetres above 0 and below the "
        "print size");
}

// Six times the enclosed volume (divergence theorem over the fanned faces): its sign tells
// whether the faces of a closed surface face outward.
double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      volume +=
          mesh.positions[face[0]].dot(mesh.positions[face[i]].cross(mesh.positions[face[i + 1]]));
  }
  return volume;
}

// The solid's thickness at every vertex: the ray along the inward normal to the first triangle of
// the surface not at that vertex (the local thickness of print_check.h).
void measure_thickness(const Mesh& mesh, PrintCheck& check, const Progress& progress) {
  const TriangleGrid grid(mesh);
  const std::vector<Eigen::Vector3d> normals = vertex_normals(mesh);
  const double reach = bounding_box(mesh).diagonal();
  const double inward = check.inward ? 1.0 : -1.0;
  const double wall = check.options.wall_mm / check.scale;
  double thinnest = std::numeric_limits<double>::infinity();
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (v % 8192 == 0)
      progress.step("thickness", static_cast<double>(v) / static_cast<double>(mesh.vertex_count()));
    if (normals[v].isZero()) continue;
    const auto hit = grid.first_hit(mesh.positions[v], inward * normals[v], reach, v);
    const double thickness = hit.triangle == kNoIndex ? 0.0 : hit.distance;
    check.thin_vertices += thickness < wall;
    if (thickness < thinnest) {
      thinnest = thickness;
      check.thinnest_at_mm = mesh.positions[v] * check.scale;
    }
  }
  check.thinnest_mm = std::isfinite(thinnest) ? thinnest * check.scale : 0.0;
}

}  // namespace

bool PrintCheck::printable() const {
  return closed && oriented && self_intersections == 0 && thin_vertices == 0;
}

std::vector<std::string> PrintCheck::problems() const {
  std::vector<std::string> out;
  if (!closed)
    out.push_back("the surface has holes (edges with one face): a printer needs a closed solid");
  else if (!oriented)
    out.push_back(
        "the faces are not consistently oriented: the slicer cannot tell inside from "
        "outside");
  if (self_intersections > 0)
    out.push_back("the surface crosses itself (" + std::to_string(self_intersections) +
                  " triangle pairs): the solid is not well defined there; choose another target "
                  "or a smaller tube radius");
  if (thin_vertices > 0) {
    const double at_least = thinnest_mm > 0 ? options.size_mm * options.wall_mm / thinnest_mm : 0;
    std::ostringstream at;
    at.precision(3);
    at << "(" << thinnest_at_mm.x() << ", " << thinnest_at_mm.y() << ", " << thinnest_at_mm.z()
       << ") mm";
    out.push_back("the solid is thinner than the " + millimetres(options.wall_mm) + " wall at " +
                  std::to_string(thin_vertices) + " vertices, thinnest " +
                  millimetres(thinnest_mm) + " at " + at.str() +
                  (at_least > 0 ? "; print it at least " + millimetres(at_least) + " large" : "") +
                  " or make the tubes thicker");
  }
  return out;
}

PrintCheck check_print(const Mesh& mesh, const PrintOptions& options, const Progress& progress) {
  check_options(options);
  PrintCheck check;
  check.options = options;
  const BoundingBox box = bounding_box(mesh);
  const double largest = (box.max - box.min).maxCoeff();
  if (!(largest > 0)) throw GeometryError("the surface has no extent: there is nothing to print");
  check.scale = options.size_mm / largest;
  check.extent_mm = (box.max - box.min) * check.scale;
  const Closure c = closure(mesh);
  check.closed = c.closed;
  check.oriented = c.oriented;
  check.inward = signed_volume(mesh) < 0;
  progress.step("self-intersections", 0.0);
  check.self_intersections = find_self_intersections(mesh, progress).triangle_pairs;
  measure_thickness(mesh, check, progress);
  return check;
}

nlohmann::ordered_json print_check_json(const PrintCheck& c) {
  const auto point = [](const Eigen::Vector3d& p) {
    return std::vector<double>{p.x(), p.y(), p.z()};
  };
  return {{"size_mm", c.options.size_mm},
          {"wall_mm", c.options.wall_mm},
          {"scale", c.scale},
          {"extent_mm", point(c.extent_mm)},
          {"closed", c.closed},
          {"oriented", c.oriented},
          {"self_intersections", c.self_intersections},
          {"thinnest_mm", c.thinnest_mm},
          {"thinnest_at_mm", point(c.thinnest_at_mm)},
          {"thin_vertices", c.thin_vertices},
          {"printable", c.printable()},
          {"problems", c.problems()}};
}

Mesh print_mesh(const Mesh& mesh, const PrintCheck& check) {
  Mesh out = mesh;
  const BoundingBox box = bounding_box(mesh);
  const Eigen::Vector3d centre = (box.min + box.max) / 2;
  const Eigen::Vector3d shift(centre.x(), centre.y(), box.min.z());
  for (Eigen::Vector3d& p : out.positions) p = (p - shift) * check.scale;
  if (check.inward)
    for (std::size_t f = 0; f < out.face_count(); ++f)
      std::reverse(out.face_vertices.begin() + out.face_offsets[f] + 1,
                   out.face_vertices.begin() + out.face_offsets[f + 1]);
  return out;
}

}  // namespace tessera
