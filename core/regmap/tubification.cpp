#include "regmap/tubification.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Geometry>

#include "base/error.h"
#include "base/limits.h"
#include "regmap/tube_curve.h"

namespace tessera::regmap {

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;
constexpr int kFineSteps = 64;  // samples per Bezier arc, for the rotation-minimizing frame

// ---- The junction plate (Sec. 9.4, Fig. 9.13c) -------------------------------------------------

// The region of one quarter tube over the tangent plane, in the frame (x along the dart, y towards
// the quarter tube's hole), as a Coons patch over s (node 0 .. tube start 1) and w (seam 0 ..
// rim 1). Its sides: the dart's axis (w = 0), the tube's cross-section (s = 1), the fillet arc
// (w = 1) and the bisector between two darts (s = 0), which the next dart's patch mirrors.
class SectorPatch {
 public:
  SectorPatch(const TubeShape& shape, int valence) : half_angle_(kPi / valence), shape_(shape) {
    const double offset = shape.radius + shape.fillet;
    centre_ = {shape.reach, offset};  // of the fillet circle, tangent to both tubes' sides
    gap_ = fillet(0.0);
    end_ = {shape.reach, shape.radius};
  }

  Vector2d at(double s, double w) const {
    const Vector2d axis(s * shape_.reach, 0.0), rim = fillet(s);
    const Vector2d bisector = w * gap_, section(shape_.reach, w * shape_.radius);
    const Vector2d corners =
        (1 - s) * w * gap_ + s * (1 - w) * Vector2d(shape_.reach, 0.0) + s * w * end_;
    return (1 - w) * axis + w * rim + (1 - s) * bisector + s * section - corners;
  }

 private:
  // From the point nearest the node (on the bisector, s = 0) to the tube's side (s = 1).
  Vector2d fillet(double s) const {
    const double angle = kPi + half_angle_ + s * (kPi / 2 - half_angle_);
    return centre_ + shape_.fillet * Vector2d(std::cos(angle), std::sin(angle));
  }

  double half_angle_;
  TubeShape shape_;
  Vector2d centre_, gap_, end_;
};

// ---- Tubes along the edges --------------------------------------------------------------------

struct Ring {
  Vector3d point, tangent, up;
  Vector3d left() const { return up.cross(tangent); }
};

// Sec. 9.4, Fig. 9.11: "the normals along each segment are interpolated from the junctions".
// A rotation-minimizing frame (double reflection) carries A's normal along the curve; the twist it
// is off B's normal by at the end is spread over the arc length.
std::vector<Ring> frame_curve(const std::vector<Vector3d>& points,
                              const std::vector<Vector3d>& tangents, const Vector3d& up_a,
                              const Vector3d& up_b) {
  std::vector<Ring> rings(points.size());
  std::vector<double> length(points.size(), 0.0);
  rings[0] = {points[0], tangents[0], up_a};
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vector3d v1 = points[i + 1] - points[i];
    const double c1 = v1.squaredNorm();
    length[i + 1] = length[i] + std::sqrt(c1);
    Vector3d up = rings[i].up, tangent = rings[i].tangent;
    if (c1 > 0) {
      up -= (2 / c1) * v1.dot(up) * v1;
      tangent -= (2 / c1) * v1.dot(tangent) * v1;
    }
    const Vector3d v2 = tangents[i + 1] - tangent;
    const double c2 = v2.squaredNorm();
    if (c2 > 0) up -= (2 / c2) * v2.dot(up) * v2;
    rings[i + 1] = {points[i + 1], tangents[i + 1], up.normalized()};
  }
  const Ring& last = rings.back();
  const double twist = std::atan2(last.up.cross(up_b).dot(last.tangent), last.up.dot(up_b));
  for (std::size_t i = 0; i < rings.size(); ++i) {
    const double angle = length.back() > 0 ? twist * length[i] / length.back() : 0.0;
    rings[i].up = Eigen::AngleAxisd(angle, rings[i].tangent) * rings[i].up;
  }
  return rings;
}

// Samples of arcs [first, last), kFineSteps on each, appended without repeating the first point of
// an arc after the first.
void sample_arcs(const std::vector<Bezier>& arcs, std::size_t first, std::size_t last,
                 std::vector<Vector3d>& points, std::vector<Vector3d>& tangents) {
  for (std::size_t k = first; k < last; ++k) {
    for (int i = points.empty() ? 0 : 1; i <= kFineSteps; ++i) {
      const double t = static_cast<double>(i) / kFineSteps;
      points.push_back(arcs[k].at(t));
      const Vector3d chord = arcs[k].p[3] - arcs[k].p[0];
      tangents.push_back(unit_or(arcs[k].derivative(t), unit_or(chord, Vector3d::UnitX())));
    }
  }
}

// Cumulative arc length of fine samples [from, to].
std::vector<double> arc_lengths(const std::vector<Ring>& fine, std::size_t from, std::size_t to) {
  std::vector<double> length = {0.0};
  for (std::size_t i = from; i < to; ++i)
    length.push_back(length.back() + (fine[i + 1].point - fine[i].point).norm());
  return length;
}

// The fine samples from index `from` to `to` picked at `along` equal steps of arc length (the
// first only when `rings` is empty).
void pick_rings(const std::vector<Ring>& fine, std::size_t from, std::size_t to, int along,
                std::vector<Ring>& rings) {
  const std::vector<double> length = arc_lengths(fine, from, to);
  std::size_t k = 0;
  for (int r = rings.empty() ? 0 : 1; r <= along; ++r) {
    const double target = length.back() * r / along;
    while (k + 1 < length.size() && length[k + 1] <= target) ++k;
    if (k + 1 < length.size() && length[k + 1] - target < target - length[k]) ++k;
    rings.push_back(fine[from + (r == along ? length.size() - 1 : k)]);
  }
}

// The 2 * along + 1 rings of an edge, from its first dart's junction to its second's, the middle
// one at the edge's midpoint. `along` is the shape's, or more on a long tube, so that rings are
// at most ring_spacing apart.
std::vector<Ring> edge_rings(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                             const JunctionOrder& order, std::size_t edge, const TubeShape& shape) {
  const auto [dart_a, dart_b] = order.edge_darts[edge];
  const auto node_a = static_cast<std::size_t>(graph.dart_node[static_cast<std::size_t>(dart_a)]);
  const auto node_b = static_cast<std::size_t>(graph.dart_node[static_cast<std::size_t>(dart_b)]);
  const Vector3d a = dart_direction(embedded, graph, order, dart_a);
  const Vector3d b = dart_direction(embedded, graph, order, dart_b);
  const std::vector<Bezier> arcs = edge_centreline(embedded, graph, order, edge);
  const std::size_t middle_arc = first_half_arcs(embedded.edge_path[edge].size());
  std::vector<Vector3d> points, tangents;
  sample_arcs(arcs, 0, middle_arc, points, tangents);
  const std::size_t middle = points.size() - 1;
  sample_arcs(arcs, middle_arc, arcs.size(), points, tangents);
  // The curve leaves A along a and enters B against b, exactly.
  tangents.front() = a;
  tangents.back() = -b;
  const std::vector<Ring> fine = frame_curve(points, tangents, embedded.node_frame[node_a].col(2),
                                             embedded.node_frame[node_b].col(2));
  const double longer_half = std::max(arc_lengths(fine, 0, middle).back(),
                                      arc_lengths(fine, middle, fine.size() - 1).back());
  const int along =
      std::max(shape.along, static_cast<int>(std::ceil(longer_half / shape.ring_spacing)));
  std::vector<Ring> rings;
  pick_rings(fine, 0, middle, along, rings);
  pick_rings(fine, middle, fine.size() - 1, along, rings);
  return rings;
}

// ---- Vertices and faces -----------------------------------------------------------------------

// Where each vertex of the surface lives: the two poles of every junction, the gap meridians
// between neighbouring darts (one per dart: the gap after it, counterclockwise), the junction
// plate of every dart, the rings of every edge. A dart's own angle index j runs around its tube
// from the top seam (0) over its left side to the bottom seam (across) and back over its right
// side; an edge's rings use the angle index of its first dart (A).
class SurfaceLayout {
 public:
  // `along[e]`: the rings of edge e number 2 * along[e] + 1.
  SurfaceLayout(const EdgeGraph& graph, const JunctionOrder& order, const TubeShape& shape,
                std::vector<int> along)
      : graph_(graph),
        order_(order),
        shape_(shape),
        around_(2 * shape.across),
        along_(std::move(along)) {
    const std::size_t darts = graph.dart_node.size();
    meridian_base_ = 2 * graph.node_count;
    plate_base_ = meridian_base_ + darts * static_cast<std::size_t>(shape.across - 1);
    std::size_t next =
        plate_base_ + darts * static_cast<std::size_t>((shape.junction - 1) * around_);
    for (int rings : along_) {
      ring_base_.push_back(next);
      next += static_cast<std::size_t>((2 * rings + 1) * around_);
    }
    vertex_count_ = next;
  }

  std::size_t vertex_count() const { return vertex_count_; }
  // Columns of quads of a quarter tube on dart d: the junction's and its edge's along.
  int columns(std::int32_t dart) const {
    return shape_.junction +
           along_[static_cast<std::size_t>(graph_.dart_edge[static_cast<std::size_t>(dart)])];
  }

  Index pole(std::size_t node, bool top) const { return to_index(2 * node + (top ? 0 : 1)); }
  Index meridian(std::size_t dart, int j) const {
    return to_index(meridian_base_ + dart * static_cast<std::size_t>(shape_.across - 1) +
                    static_cast<std::size_t>(j - 1));
  }
  Index plate(std::size_t dart, int i, int j) const {
    return to_index(
        plate_base_ +
        (dart * static_cast<std::size_t>(shape_.junction - 1) + static_cast<std::size_t>(i - 1)) *
            static_cast<std::size_t>(around_) +
        static_cast<std::size_t>(j));
  }
  Index ring(std::size_t edge, int i, int j) const {
    return to_index(ring_base_[edge] +
                    static_cast<std::size_t>(i) * static_cast<std::size_t>(around_) +
                    static_cast<std::size_t>(j));
  }

  // Vertex (i, j) of the quarter tube on the left (or right) of dart d: i from the node (0) to the
  // midpoint (columns(d)), j from the top seam (0) to the bottom seam (across).
  Index quarter_tube_vertex(std::int32_t dart, bool left, int i, int j) const {
    const auto d = static_cast<std::size_t>(dart);
    const int across = shape_.across;
    if (i == 0) {
      const auto node = static_cast<std::size_t>(graph_.dart_node[d]);
      if (j == 0 || j == across) return pole(node, j == 0);
      return meridian(left ? d : static_cast<std::size_t>(order_.prev_around[d]), j);
    }
    const int own = left ? j : (around_ - j) % around_;
    if (i < shape_.junction) return plate(d, i, own);
    const auto edge = static_cast<std::size_t>(graph_.dart_edge[d]);
    const bool first = order_.edge_darts[edge][0] == dart;
    const int along = i - shape_.junction;
    return ring(edge, first ? along : 2 * along_[edge] - along,
                first ? own : (around_ - own) % around_);
  }

 private:
  static Index to_index(std::size_t i) { return static_cast<Index>(i); }

  const EdgeGraph& graph_;
  const JunctionOrder& order_;
  TubeShape shape_;
  int around_;
  std::vector<int> along_;
  std::vector<std::size_t> ring_base_;
  std::size_t meridian_base_ = 0, plate_base_ = 0, vertex_count_ = 0;
};

// The point at angle index j (of 2 * across) around a ring frame.
Vector3d around_ring(const Vector3d& centre, const Vector3d& up, const Vector3d& left,
                     double radius, int j, int across) {
  const double phi = kPi * j / across;
  return centre + radius * (std::cos(phi) * up + std::sin(phi) * left);
}

void place_junctions(const EmbeddedGraph& embedded, const EdgeGraph& graph,
                     const JunctionOrder& order, const TubeShape& shape,
                     const SurfaceLayout& layout, std::vector<Vector3d>& positions) {
  const SectorPatch patch(shape, order.valence);
  const int across = shape.across;
  for (std::size_t v = 0; v < graph.node_count; ++v) {
    const Vector3d& centre = embedded.node_position[v];
    const Vector3d n = embedded.node_frame[v].col(2);
    positions[layout.pole(v, true)] = centre + shape.radius * n;
    positions[layout.pole(v, false)] = centre - shape.radius * n;
    for (std::int32_t dart : order.node_darts[v]) {
      const auto d = static_cast<std::size_t>(dart);
      const Vector3d x = dart_direction(embedded, graph, order, dart);
      const Vector3d y = n.cross(x);
      auto lift = [&](const Vector2d& planar, double phi, double side) {
        return Vector3d(centre + planar.x() * x + side * planar.y() * y +
                        shape.radius * std::cos(phi) * n);
      };
      for (int j = 1; j < across; ++j) {
        const double phi = kPi * j / across;
        positions[layout.meridian(d, j)] = lift(patch.at(0.0, std::sin(phi)), phi, 1.0);
      }
      for (int i = 1; i < shape.junction; ++i) {
        const double s = static_cast<double>(i) / shape.junction;
        for (int j = 0; j < 2 * across; ++j) {
          const double phi = kPi * j / across;
          const double side = j > across ? -1.0 : 1.0;
          positions[layout.plate(d, i, j)] = lift(patch.at(s, std::abs(std::sin(phi))), phi, side);
        }
      }
    }
  }
}

void place_tubes(const std::vector<std::vector<Ring>>& rings, const TubeShape& shape,
                 const SurfaceLayout& layout, std::vector<Vector3d>& positions) {
  for (std::size_t e = 0; e < rings.size(); ++e) {
    for (std::size_t i = 0; i < rings[e].size(); ++i) {
      const Ring& r = rings[e][i];
      for (int j = 0; j < 2 * shape.across; ++j)
        positions[layout.ring(e, static_cast<int>(i), j)] =
            around_ring(r.point, r.up, r.left(), shape.radius, j, shape.across);
    }
  }
}

// The quads of one quarter tube, counterclockwise seen from outside: along the dart, then towards
// the quarter tube's hole is counterclockwise about the top normal on the left, clockwise on the
// right.
void add_quarter_tube(const SurfaceLayout& layout, std::int32_t dart, bool left, Element tile,
                      const TubeShape& shape, TubifiedSurface& surface,
                      std::vector<std::int32_t>& tiles) {
  const int columns = layout.columns(dart);
  QuarterTubeGrid& grid = surface.grids[static_cast<std::size_t>(tile)];
  grid.columns = columns;
  grid.across = shape.across;
  grid.counterclockwise = left;
  for (int i = 0; i <= columns; ++i) {
    for (int j = 0; j <= shape.across; ++j)
      grid.vertex.push_back(layout.quarter_tube_vertex(dart, left, i, j));
  }
  Mesh& mesh = surface.mesh;
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < shape.across; ++j) {
      const Index a = layout.quarter_tube_vertex(dart, left, i, j);
      const Index b = layout.quarter_tube_vertex(dart, left, i + 1, j);
      const Index c = layout.quarter_tube_vertex(dart, left, i + 1, j + 1);
      const Index d = layout.quarter_tube_vertex(dart, left, i, j + 1);
      if (left)
        mesh.add_face({a, b, c, d});
      else
        mesh.add_face({a, d, c, b});
      tiles.push_back(tile);
    }
  }
}

}  // namespace

TubeShape tube_shape(const TubeOptions& options, int valence) {
  if (valence < 3)
    throw InputError("the edge graph has junctions of valence " + std::to_string(valence) +
                     "; a regular surface needs at least 3 tubes per junction (q >= 3)");
  const auto finite_positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (options.radius != 0.0 && !finite_positive(options.radius))
    throw InputError("the tube radius must be a positive number (or 0 for automatic), got " +
                     std::to_string(options.radius));
  if (!finite_positive(options.roundness))
    throw InputError("the junction roundness must be a positive number, got " +
                     std::to_string(options.roundness));
  if (options.smoothness < 2 || options.smoothness > 32)
    throw InputError("the smoothness (quads across a quarter tube) must be 2..32, got " +
                     std::to_string(options.smoothness));
  const double half_angle = std::numbers::pi / valence;
  TubeShape shape;
  shape.radius = options.radius > 0.0
                     ? options.radius
                     : 0.15 * std::min(1.0, std::tan(half_angle) / std::tan(std::numbers::pi / 6));
  shape.fillet = options.roundness * shape.radius;
  shape.reach = (shape.radius + shape.fillet) / std::tan(half_angle);
  // A tube bends within about an arm; an arm of sqrt(2 r) keeps its curvature below 1 / r for the
  // bends of about a unit that the placements make.
  shape.arm = std::max(2.5 * shape.radius, std::sqrt(2.0 * shape.radius));
  shape.clearance = 4.0 * shape.radius;
  shape.across = options.smoothness;
  shape.along = options.smoothness;
  shape.junction = std::max(2, (3 * options.smoothness + 3) / 4);
  shape.ring_spacing = 1.0 / options.smoothness;
  return shape;
}

TubifiedSurface tubify(const EmbeddedGraph& embedded, const LineGraph& line,
                       const JunctionOrder& order, const TubeShape& shape, std::size_t max_faces) {
  const EdgeGraph& graph = line.graph;
  std::vector<std::vector<Ring>> rings;
  std::vector<int> along;
  std::size_t faces = 0;
  for (std::size_t e = 0; e < graph.edge_count; ++e) {
    rings.push_back(edge_rings(embedded, graph, order, e, shape));
    along.push_back(static_cast<int>(rings.back().size() / 2));
    faces += 4 * static_cast<std::size_t>(shape.across * (shape.junction + along.back()));
  }
  check_limit(faces, max_faces, "the regular surface's mesh (faces)", "--max-faces");
  const SurfaceLayout layout(graph, order, shape, std::move(along));
  TubifiedSurface surface;
  surface.grids.resize(graph.dart_element.size() * 2);
  Mesh& mesh = surface.mesh;
  mesh.positions.assign(layout.vertex_count(), Vector3d::Zero());
  place_junctions(embedded, graph, order, shape, layout, mesh.positions);
  place_tubes(rings, shape, layout, mesh.positions);
  std::vector<std::int32_t> tiles;
  for (std::size_t d = 0; d < graph.dart_element.size(); ++d) {
    const Element g = graph.dart_element[d];
    const auto dart = static_cast<std::int32_t>(d);
    add_quarter_tube(layout, dart, true, g, shape, surface, tiles);
    add_quarter_tube(layout, dart, false, line.partner[static_cast<std::size_t>(g)], shape, surface,
                     tiles);
  }
  mesh.face_attributes[kTileAttribute] = std::move(tiles);
  return surface;
}

}  // namespace tessera::regmap
