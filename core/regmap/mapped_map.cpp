#include "regmap/mapped_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include <Eigen/LU>
#include <Eigen/SparseLU>

#include "base/disjoint_sets.h"
#include "base/error.h"
#include "mesh/connectivity.h"
#include "mesh/edge_table.h"
#include "mesh/self_intersection.h"
#include "mesh/topology.h"
#include "regmap/surface_group.h"

namespace tessera::regmap {

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kOnSide = 1e-9;  // Klein distances this small lie on a line

// The Klein model's point of a Poincare disk point, and back: geodesics become chords.
Vector2d klein(const Point& p) {
  const Complex z = to_plane(p);
  const double scale = 2.0 / (1.0 + std::norm(z));
  return {scale * z.real(), scale * z.imag()};
}
Point poincare(const Vector2d& k) {
  const double scale = 1.0 / (1.0 + std::sqrt(std::max(0.0, 1.0 - k.squaredNorm())));
  return Point{Complex(scale * k.x(), scale * k.y()), 1.0};
}

double cross(const Vector2d& u, const Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

enum class VertexKind { Interior, MapVertex, EdgeMidpoint };

VertexKind kind_of(Corner c) {
  return c == kN   ? VertexKind::MapVertex
         : c == kO ? VertexKind::EdgeMidpoint
                   : VertexKind::Interior;
}

// The quadrilateral's sides as (s, t) runs: side i goes from corner kSideStart[i] to
// kSideEnd[i]; L1 is t = 0 (P1 -> P2), L2 s = 1 (P2 -> P3), L3 t = 1 (P4 -> P3), L4 s = 0
// (P1 -> P4).
constexpr std::array<std::size_t, 4> kSideStart = {0, 1, 3, 0}, kSideEnd = {1, 2, 2, 3};

// A quarter tube's quadrilateral cut out of M's tiling and triangulated: one disk in (s, t).
struct Template {
  std::vector<Vector2d> st;  // per vertex
  std::vector<VertexKind> kind;
  std::vector<std::array<std::int32_t, 3>> triangles;  // counterclockwise in (s, t)
  std::vector<Element> triangle_flag;                  // M's flag (cover element) of each
  std::vector<std::array<std::int32_t, 2>> map_edges;  // template edges along N-O sides
  std::array<std::vector<std::pair<double, std::int32_t>>, 4> side;  // (parameter, vertex)
  std::vector<std::pair<Element, double>> pieces;  // flag and hyperbolic area of each piece
};

// A convex polygon in Klein coordinates whose edge i (vertex i -> i+1) lies on a side of M's
// triangle (tri_side, or -1 where it was cut).
struct Polygon {
  std::vector<Vector2d> k;
  std::vector<VertexKind> kind;
  std::vector<int> tri_side;
  void add(const Vector2d& x, VertexKind vk, int tri) {
    k.push_back(x);
    kind.push_back(vk);
    tri_side.push_back(tri);
  }
};

// Sutherland-Hodgman: the part of `in` left of the line a -> b (right when sign is -1).
Polygon clip(const Polygon& in, const Vector2d& a, const Vector2d& b, double sign) {
  Polygon out;
  const Vector2d d = (b - a).normalized();
  auto height = [&](const Vector2d& x) { return sign * cross(d, x - a); };
  const std::size_t n = in.k.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const double hp = height(in.k[i]), hq = height(in.k[j]);
    const bool p_on = std::abs(hp) <= kOnSide, q_on = std::abs(hq) <= kOnSide;
    const bool p_in = hp >= -kOnSide, q_in = hq >= -kOnSide;
    const Vector2d cut = in.k[i] + hp / (hp - hq) * (in.k[j] - in.k[i]);
    if (p_in && q_in) {
      out.add(in.k[i], in.kind[i], in.tri_side[i]);
    } else if (p_in) {
      out.add(in.k[i], in.kind[i], p_on ? -1 : in.tri_side[i]);
      if (!p_on) out.add(cut, VertexKind::Interior, -1);
    } else if (q_in && !q_on) {
      out.add(cut, VertexKind::Interior, in.tri_side[i]);
    }
  }
  // Drop repeated vertices (a corner on the line): the later one keeps its outgoing edge.
  Polygon clean;
  for (std::size_t i = 0; i < out.k.size(); ++i) {
    const std::size_t j = (i + 1) % out.k.size();
    if (out.k.size() > 1 && (out.k[i] - out.k[j]).norm() <= kOnSide) {
      if (out.kind[i] != VertexKind::Interior) out.kind[j] = out.kind[i];
      continue;
    }
    clean.add(out.k[i], out.kind[i], out.tri_side[i]);
  }
  return clean;
}

// The hyperbolic area of a convex polygon: (n - 2) pi minus its angles.
double polygon_area(Geometry g, const std::vector<Point>& p) {
  const std::size_t n = p.size();
  double angles = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Isometry back = inverse(g, translation_to(g, to_plane(p[i])));
    const Complex u = to_plane(apply(g, back, p[(i + 1) % n]));
    const Complex w = to_plane(apply(g, back, p[(i + n - 1) % n]));
    angles += std::abs(std::arg(w / u));
  }
  return (double(n) - 2) * std::numbers::pi - angles;
}

// Points closer than a billionth are one vertex: a hash of cells a thousand times larger.
class Welder {
 public:
  // The index of an earlier point of `points` this close to x, or -1.
  std::int32_t find(const Vector2d& x, const std::vector<Vector2d>& points) const {
    const auto [i, j] = cell(x);
    for (long long di = -1; di <= 1; ++di) {
      for (long long dj = -1; dj <= 1; ++dj) {
        const auto found = cells_.find({i + di, j + dj});
        if (found == cells_.end()) continue;
        for (std::int32_t v : found->second)
          if ((points[static_cast<std::size_t>(v)] - x).norm() < kWeld) return v;
      }
    }
    return -1;
  }
  void add(const Vector2d& x, std::int32_t v) { cells_[cell(x)].push_back(v); }

 private:
  static std::pair<long long, long long> cell(const Vector2d& x) {
    return {std::llround(x.x() / kCell), std::llround(x.y() / kCell)};
  }
  static constexpr double kCell = 1e-6, kWeld = 1e-9;
  std::map<std::pair<long long, long long>, std::vector<std::int32_t>> cells_;
};

// A point whose farthest corner of `quad` is nearly as close as can be (Badoiu and Clarkson's
// iteration: step towards the farthest corner by a shrinking fraction). The template works in
// the Klein model about that point: about a corner of the quadrilateral instead, its far corners
// would lie within 1e-7 of the disk's rim, where Klein distances shrink a millionfold and every
// tolerance below would mean a thousandth of the tiling's triangle.
Point minimax_centre(Geometry g, const std::array<Point, 4>& quad) {
  Point centre = quad[0];
  for (int k = 1; k <= 64; ++k) {
    const auto far =
        std::max_element(quad.begin(), quad.end(), [&](const Point& u, const Point& v) {
          return distance(g, centre, u) < distance(g, centre, v);
        });
    centre = geodesic_point(g, centre, *far, 1.0 / (k + 1));
  }
  return centre;
}

class TemplateBuilder {
 public:
  // `quad` in the cover, `sign` +1 when it is counterclockwise, -1 when clockwise.
  TemplateBuilder(const FiniteGroup& source, const std::array<Point, 4>& quad, double sign)
      : cover_(source), sign_(sign) {
    const Geometry g = cover_.geometry();
    recentre_ = inverse(g, translation_to(g, to_plane(minimax_centre(g, quad))));
    for (std::size_t i = 0; i < 4; ++i) {
      corners_[i] = apply(g, recentre_, quad[i]);
      klein_corners_[i] = klein(corners_[i]);
    }
    cut_pieces();
  }

  Template build(int n) {
    const Geometry g = cover_.geometry();
    for (const auto& [element, polygon] : pieces_) {
      std::vector<Point> points;
      for (const Vector2d& k : polygon.k) points.push_back(poincare(k));
      result_.pieces.push_back({element, polygon_area(g, points)});
      add_piece(element, polygon, n);
    }
    assign_st();
    return std::move(result_);
  }

 private:
  Vector2d corner(const CoverTriangle& t, Corner c) const {
    return klein(apply(cover_.geometry(), recentre_, cover_.corner(t, c)));
  }

  // The cover's triangles that meet the quadrilateral, clipped to it: a flood fill from the
  // triangles around P1 over sides whose neighbour keeps a part.
  void cut_pieces() {
    auto key = [](const Vector2d& x) {
      return std::pair<long long, long long>(std::llround(x.x() * 1e8), std::llround(x.y() * 1e8));
    };
    std::set<std::pair<long long, long long>> seen;
    std::vector<CoverTriangle> queue;
    auto visit = [&](const CoverTriangle& t) {
      const Vector2d inside = (corner(t, kM) + corner(t, kN) + corner(t, kO)) / 3.0;
      if (!seen.insert(key(inside)).second) return;
      Polygon piece = clipped(t);
      if (piece.k.size() < 3) return;
      pieces_.push_back({t.element, std::move(piece)});
      queue.push_back(t);
    };
    // Around P1: D0 and the triangles reached by turning about its corner there.
    const Point p1 = cover_.corner(CoverTriangle{}, kN);
    const Corner apex =
        same_point(cover_.geometry(), apply(cover_.geometry(), recentre_, p1), corners_[0]) ? kN
                                                                                            : kM;
    CoverTriangle t;
    Side side = Side::MN;
    for (int k = 0; k < 2 * cover_.sectors(apex); ++k) {
      visit(t);
      t = cover_.across(t, side);
      side = side == Side::MN ? (apex == kN ? Side::NO : Side::MO) : Side::MN;
    }
    for (std::size_t i = 0; i < queue.size(); ++i) {
      for (Side s : kSides) visit(cover_.across(queue[i], s));
    }
  }

  Polygon clipped(const CoverTriangle& t) const {
    std::array<Vector2d, 3> k = {corner(t, kM), corner(t, kN), corner(t, kO)};
    Polygon polygon;
    if (cross(k[1] - k[0], k[2] - k[0]) > 0) {
      polygon.add(k[0], kind_of(kM), static_cast<int>(Side::MN));
      polygon.add(k[1], kind_of(kN), static_cast<int>(Side::NO));
      polygon.add(k[2], kind_of(kO), static_cast<int>(Side::MO));
    } else {
      polygon.add(k[0], kind_of(kM), static_cast<int>(Side::MO));
      polygon.add(k[2], kind_of(kO), static_cast<int>(Side::NO));
      polygon.add(k[1], kind_of(kN), static_cast<int>(Side::MN));
    }
    for (std::size_t i = 0; i < 4 && polygon.k.size() >= 3; ++i)
      polygon = clip(polygon, klein_corners_[i], klein_corners_[(i + 1) % 4], sign_);
    if (polygon.k.size() < 3) return {};
    double area = 0;
    for (std::size_t i = 0; i < polygon.k.size(); ++i)
      area += cross(polygon.k[i], polygon.k[(i + 1) % polygon.k.size()]);
    return std::abs(area) > 1e-14 ? polygon : Polygon{};
  }

  // The template vertex at Klein point x (welded with an earlier one at the same point).
  std::int32_t vertex(const Vector2d& x, VertexKind kind) {
    if (const std::int32_t v = welded_.find(x, klein_); v >= 0) {
      if (kind != VertexKind::Interior) result_.kind[static_cast<std::size_t>(v)] = kind;
      return v;
    }
    const auto v = static_cast<std::int32_t>(klein_.size());
    klein_.push_back(x);
    welded_.add(x, v);
    result_.kind.push_back(kind);
    return v;
  }

  // The point a fraction f from u to v along their geodesic, in Klein coordinates.
  Vector2d along(const Vector2d& u, const Vector2d& v, double f) const {
    return klein(geodesic_point(cover_.geometry(), poincare(u), poincare(v), f));
  }

  // A piece as a fan from its centroid, each fan triangle (c, b_i, b_i+1) subdivided n x n; points
  // on the triangle's sides at equal hyperbolic steps (the same from both sides of a side, and on
  // a quadrilateral side the same in every quarter tube), inside at Klein barycentres.
  void add_piece(Element element, const Polygon& polygon, int n) {
    Vector2d centre = Vector2d::Zero();
    for (const Vector2d& k : polygon.k) centre += k / double(polygon.k.size());
    const std::size_t m = polygon.k.size();
    for (std::size_t e = 0; e < m; ++e) {
      const Vector2d a = centre, b = polygon.k[e], c = polygon.k[(e + 1) % m];
      std::vector<std::vector<std::int32_t>> grid(static_cast<std::size_t>(n) + 1);
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; i + j <= n; ++j) {
          Vector2d x;
          VertexKind kind = VertexKind::Interior;
          if (i + j == n) {
            x = along(b, c, double(j) / n);
            if (j == 0) kind = polygon.kind[e];
            if (j == n) kind = polygon.kind[(e + 1) % m];
          } else if (j == 0) {
            x = along(a, b, double(i) / n);
          } else if (i == 0) {
            x = along(a, c, double(j) / n);
          } else {
            x = a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a);
          }
          grid[static_cast<std::size_t>(i)].push_back(vertex(x, kind));
        }
      }
      auto at = [&](int i, int j) {
        return grid[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      };
      for (int i = 0; i < n; ++i) {
        for (int j = 0; i + j < n; ++j) {
          add_triangle({at(i, j), at(i + 1, j), at(i, j + 1)}, element);
          if (i + j + 2 <= n) add_triangle({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, element);
        }
      }
      if (polygon.tri_side[e] == static_cast<int>(Side::NO)) {
        for (int j = 0; j < n; ++j)
          result_.map_edges.push_back({at(n - j, j), at(n - j - 1, j + 1)});
      }
    }
  }

  void add_triangle(const std::array<std::int32_t, 3>& v, Element flag) {
    result_.triangles.push_back(v);
    result_.triangle_flag.push_back(flag);
  }

  // Arc-length parameter of x on side i, or -1 when x is not on it.
  double side_parameter(std::size_t i, const Vector2d& x) const {
    const Vector2d a = klein_corners_[kSideStart[i]], b = klein_corners_[kSideEnd[i]];
    const Vector2d d = b - a;
    const double along_side = d.dot(x - a) / d.squaredNorm();
    if (std::abs(cross(d.normalized(), x - a)) > 1e-7 || along_side < -1e-7 ||
        along_side > 1 + 1e-7)
      return -1;
    const Geometry g = cover_.geometry();
    const Point start = corners_[kSideStart[i]], end = corners_[kSideEnd[i]];
    return std::clamp(distance(g, start, poincare(x)) / distance(g, start, end), 0.0, 1.0);
  }

  // (s, t): the sides at their arc-length parameters (so that a side's points sit at the same
  // (s, t) in both quarter tubes that share it), the rest by Floater's mean-value map of the
  // template onto the unit square (positive weights and a convex boundary: no folds).
  void assign_st() {
    const std::size_t nv = klein_.size();
    result_.st.assign(nv, Vector2d::Zero());
    std::vector<bool> fixed(nv, false);
    for (std::size_t v = 0; v < nv; ++v) {
      for (std::size_t i = 0; i < 4; ++i) {
        const double p = side_parameter(i, klein_[v]);
        if (p < 0) continue;
        result_.side[i].push_back({p, static_cast<std::int32_t>(v)});
        Vector2d& st = result_.st[v];
        if (i == 0) st = {p, 0};
        if (i == 1) st = {1, p};
        if (i == 2) st = {p, 1};
        if (i == 3) st = {0, p};
        fixed[v] = true;
      }
    }
    for (auto& side : result_.side) std::sort(side.begin(), side.end());
    solve_mean_value(fixed);
    for (auto& tri : result_.triangles) {
      const Vector2d e1 = result_.st[static_cast<std::size_t>(tri[1])] -
                          result_.st[static_cast<std::size_t>(tri[0])];
      const Vector2d e2 = result_.st[static_cast<std::size_t>(tri[2])] -
                          result_.st[static_cast<std::size_t>(tri[0])];
      if (cross(e1, e2) < 0) std::swap(tri[1], tri[2]);
    }
  }

  void solve_mean_value(const std::vector<bool>& fixed) {
    const std::size_t nv = klein_.size();
    std::vector<int> unknown(nv, -1);
    int count = 0;
    for (std::size_t v = 0; v < nv; ++v)
      if (!fixed[v]) unknown[v] = count++;
    if (count == 0) return;
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(count, 2);
    for (const auto& tri : result_.triangles) {
      for (std::size_t c = 0; c < 3; ++c) {
        const auto i = static_cast<std::size_t>(tri[c]);
        if (fixed[i]) continue;
        const Vector2d xi = klein_[i];
        const std::array<std::size_t, 2> other = {static_cast<std::size_t>(tri[(c + 1) % 3]),
                                                  static_cast<std::size_t>(tri[(c + 2) % 3])};
        const Vector2d u = klein_[other[0]] - xi, w = klein_[other[1]] - xi;
        const double half = 0.5 * std::atan2(std::abs(cross(u, w)), u.dot(w));
        for (std::size_t j : other) {
          const double weight = std::tan(half) / (klein_[j] - xi).norm();
          entries.push_back({unknown[i], unknown[i], weight});
          if (fixed[j])
            rhs.row(unknown[i]) += weight * result_.st[j].transpose();
          else
            entries.push_back({unknown[i], unknown[j], -weight});
        }
      }
    }
    Eigen::SparseMatrix<double> matrix(count, count);
    matrix.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(matrix);
    if (solver.info() != Eigen::Success)
      throw Error("the quarter tube's template has no mean-value map to the unit square");
    const Eigen::MatrixX2d st = solver.solve(rhs);
    for (std::size_t v = 0; v < nv; ++v)
      if (!fixed[v]) result_.st[v] = st.row(unknown[v]).transpose();
  }

  Cover cover_;
  double sign_;
  Isometry recentre_;
  std::array<Point, 4> corners_;
  std::array<Vector2d, 4> klein_corners_;
  std::vector<std::pair<Element, Polygon>> pieces_;
  std::vector<Vector2d> klein_;
  Welder welded_;
  Template result_;
};

// Where a vertex of the drawing lies on the quarter tube's grid: in cell (i, j), in its triangle
// below the diagonal (i, j) - (i + 1, j + 1) or above it (the surface's quads are fanned from
// (i, j), mesh/triangulate), at barycentric coordinates over that triangle's corners.
struct GridLocation {
  int i = 0, j = 0;
  bool upper = false;
  Vector3d weights = Vector3d::Zero();
};

// The corners of a cell's two triangles, lower and upper, as steps (di, dj) from its (i, j) node,
// in the order GridLocation's weights take them.
constexpr std::array<std::array<std::array<int, 2>, 3>, 2> kGridTriangle = {
    {{{{0, 0}, {1, 0}, {1, 1}}}, {{{0, 0}, {1, 1}, {0, 1}}}}};

// A template laid over the grid: its triangles cut by the grid's triangles, so that every
// triangle of the drawing lies in one triangle of the surface (the drawing is a subdivision of
// the surface mesh and has its self-intersections, no others) and in one of M's flags.
struct Overlay {
  Template shape;
  std::vector<GridLocation> location;  // per vertex
};

// Removes the vertices the overlay does not need (they come from the template's own triangles,
// which only carry M's flags): a vertex inside a grid triangle and off M's edges, or on one grid
// line and off M's edges, or on one of M's edges inside a grid triangle, is merged into a
// neighbour (along the line or edge it lies on) while no triangle turns over or degenerates and
// the triangulation stays a disk (the two vertices' common neighbours are the edge's two
// opposite corners). What stays: the grid's nodes, M's vertices and edge midpoints, M's
// edges' crossings with the grid lines, the sides' vertices. Every triangle still lies in one
// grid triangle and one of M's faces.
class OverlaySimplifier {
 public:
  OverlaySimplifier(Overlay& overlay, int columns, int across)
      : o_(overlay), shape_(overlay.shape), scale_(columns, across) {
    const std::size_t nv = shape_.st.size();
    around_.resize(nv);
    for (std::size_t t = 0; t < shape_.triangles.size(); ++t)
      for (std::int32_t v : shape_.triangles[t]) around_[static_cast<std::size_t>(v)].push_back(t);
    alive_.assign(shape_.triangles.size(), true);
    along_map_edge_.resize(nv);
    for (const auto& [u, v] : shape_.map_edges) {
      along_map_edge_[static_cast<std::size_t>(u)].insert(v);
      along_map_edge_[static_cast<std::size_t>(v)].insert(u);
    }
    locked_.assign(nv, false);
    for (const auto& side : shape_.side)
      for (const auto& [p, v] : side) locked_[static_cast<std::size_t>(v)] = true;
    for (std::size_t v = 0; v < nv; ++v) {
      const int lines = grid_lines(v);
      const bool on_edge = !along_map_edge_[v].empty();
      if (shape_.kind[v] != VertexKind::Interior || lines >= 2 || (lines == 1 && on_edge) ||
          (on_edge && along_map_edge_[v].size() != 2))
        locked_[v] = true;
    }
  }

  void run() {
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t v = 0; v < shape_.st.size(); ++v)
        if (!locked_[v] && !around_[v].empty()) changed |= collapse(v);
    }
    compact();
  }

 private:
  // How many grid lines (cell sides or diagonals) vertex v lies on: its zero weights.
  int grid_lines(std::size_t v) const {
    int zeros = 0;
    for (int c = 0; c < 3; ++c) zeros += std::abs(o_.location[v].weights[c]) < kOnLine;
    return zeros;
  }

  // Whether u lies on the grid line through v (v on exactly one).
  bool on_same_line(std::size_t v, std::size_t u) const {
    const Vector2d &a = shape_.st[v], &b = shape_.st[u];
    const GridLocation& at = o_.location[v];
    const int zero = std::abs(at.weights[0]) < kOnLine   ? 0
                     : std::abs(at.weights[1]) < kOnLine ? 1
                                                         : 2;
    // The line opposite corner `zero` of the grid triangle, through its two other corners.
    const auto& corners = kGridTriangle[at.upper];
    const auto& p = corners[static_cast<std::size_t>(zero + 1) % 3];
    const auto& q = corners[static_cast<std::size_t>(zero + 2) % 3];
    const Vector2d along(q[0] - p[0], q[1] - p[1]);
    return std::abs(cross(along.normalized(), (b - a).cwiseProduct(scale_))) < kOnLine;
  }

  bool collapse(std::size_t v) {
    std::vector<std::size_t> candidates;
    if (!along_map_edge_[v].empty()) {
      for (std::int32_t u : along_map_edge_[v]) candidates.push_back(static_cast<std::size_t>(u));
    } else {
      const bool on_line = grid_lines(v) == 1;
      for (std::size_t u : neighbours(v))
        if (!on_line || on_same_line(v, u)) candidates.push_back(u);
    }
    std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
      return (shape_.st[a] - shape_.st[v]).squaredNorm() <
             (shape_.st[b] - shape_.st[v]).squaredNorm();
    });
    for (std::size_t u : candidates)
      if (try_collapse(v, u)) return true;
    return false;
  }

  std::set<std::size_t> neighbours(std::size_t v) const {
    std::set<std::size_t> out;
    for (std::size_t t : around_[v])
      for (std::int32_t w : shape_.triangles[t])
        if (static_cast<std::size_t>(w) != v) out.insert(static_cast<std::size_t>(w));
    return out;
  }

  bool try_collapse(std::size_t v, std::size_t u) {
    std::vector<std::size_t> shared, moved;
    for (std::size_t t : around_[v]) {
      const auto& tri = shape_.triangles[t];
      (std::find(tri.begin(), tri.end(), static_cast<std::int32_t>(u)) != tri.end() ? shared
                                                                                    : moved)
          .push_back(t);
    }
    if (shared.size() != 2) return false;
    std::set<std::size_t> opposite;
    for (std::size_t t : shared)
      for (std::int32_t w : shape_.triangles[t])
        if (static_cast<std::size_t>(w) != u && static_cast<std::size_t>(w) != v)
          opposite.insert(static_cast<std::size_t>(w));
    const std::set<std::size_t> nv = neighbours(v), nu = neighbours(u);
    for (std::size_t w : nv)
      if (w != u && nu.count(w) > 0 && opposite.count(w) == 0) return false;
    for (std::size_t t : moved) {
      std::array<Vector2d, 3> p;
      for (int c = 0; c < 3; ++c) {
        const auto w = static_cast<std::size_t>(shape_.triangles[t][c]);
        p[c] = shape_.st[w == v ? u : w];
      }
      if (cross(p[1] - p[0], p[2] - p[0]) <= kMinArea) return false;
    }
    for (std::size_t t : shared) {
      alive_[t] = false;
      for (std::int32_t w : shape_.triangles[t]) {
        auto& list = around_[static_cast<std::size_t>(w)];
        list.erase(std::find(list.begin(), list.end(), t));
      }
    }
    for (std::size_t t : moved) {
      for (std::int32_t& w : shape_.triangles[t])
        if (static_cast<std::size_t>(w) == v) w = static_cast<std::int32_t>(u);
      around_[u].push_back(t);
    }
    around_[v].clear();
    if (!along_map_edge_[v].empty()) {
      for (std::int32_t w : along_map_edge_[v]) {
        auto& list = along_map_edge_[static_cast<std::size_t>(w)];
        list.erase(static_cast<std::int32_t>(v));
        if (static_cast<std::size_t>(w) != u) {
          list.insert(static_cast<std::int32_t>(u));
          along_map_edge_[u].insert(w);
        }
      }
      along_map_edge_[u].erase(static_cast<std::int32_t>(v));
      along_map_edge_[v].clear();
    }
    return true;
  }

  // Drops the removed triangles and vertices, renumbering the rest.
  void compact() {
    const std::size_t nv = shape_.st.size();
    std::vector<std::int32_t> index(nv, -1);
    Overlay out;
    for (std::size_t v = 0; v < nv; ++v) {
      if (around_[v].empty()) continue;
      index[v] = static_cast<std::int32_t>(out.shape.st.size());
      out.shape.st.push_back(shape_.st[v]);
      out.shape.kind.push_back(shape_.kind[v]);
      out.location.push_back(o_.location[v]);
    }
    for (std::size_t t = 0; t < shape_.triangles.size(); ++t) {
      if (!alive_[t]) continue;
      const auto& tri = shape_.triangles[t];
      out.shape.triangles.push_back({index[static_cast<std::size_t>(tri[0])],
                                     index[static_cast<std::size_t>(tri[1])],
                                     index[static_cast<std::size_t>(tri[2])]});
      out.shape.triangle_flag.push_back(shape_.triangle_flag[t]);
    }
    // A vertex on a side or on M's edge that the simplification took out leaves the drawing
    // nothing to glue or draw there: refused (a pairing whose quadrilateral the template cannot
    // follow), never indexed.
    auto kept = [&](std::int32_t v) {
      const std::int32_t k = index[static_cast<std::size_t>(v)];
      if (k < 0) throw Error("the quarter tube's template lost a vertex on its sides or edges");
      return k;
    };
    for (std::size_t v = 0; v < nv; ++v)
      for (std::int32_t w : along_map_edge_[v])
        if (static_cast<std::size_t>(w) > v)
          out.shape.map_edges.push_back({kept(static_cast<std::int32_t>(v)), kept(w)});
    for (std::size_t i = 0; i < 4; ++i)
      for (const auto& [p, v] : shape_.side[i]) out.shape.side[i].push_back({p, kept(v)});
    out.shape.pieces = shape_.pieces;
    o_ = std::move(out);
  }

  static constexpr double kOnLine = 1e-9, kMinArea = 1e-14;
  Overlay& o_;
  Template& shape_;
  Vector2d scale_;  // (s, t) to grid units
  std::vector<std::vector<std::size_t>> around_;
  std::vector<bool> alive_, locked_;
  std::vector<std::set<std::int32_t>> along_map_edge_;
};

class OverlayBuilder {
 public:
  OverlayBuilder(const Template& shape, int columns, int across)
      : in_(shape), columns_(columns), across_(across) {}

  Overlay build() {
    std::set<std::pair<std::int32_t, std::int32_t>> map_edges;
    for (const auto& [u, v] : in_.map_edges) map_edges.insert({std::min(u, v), std::max(u, v)});
    for (std::size_t k = 0; k < in_.triangles.size(); ++k) {
      const auto& tri = in_.triangles[k];
      std::array<bool, 3> on_map_edge{};
      for (int c = 0; c < 3; ++c)
        on_map_edge[c] = map_edges.count({std::min(tri[c], tri[(c + 1) % 3]),
                                          std::max(tri[c], tri[(c + 1) % 3])}) > 0;
      cut(k, on_map_edge);
    }
    assign_sides();
    out_.shape.pieces = in_.pieces;
    OverlaySimplifier(out_, columns_, across_).run();
    return std::move(out_);
  }

 private:
  // Template triangle k clipped to every grid triangle its bounding box meets.
  void cut(std::size_t k, const std::array<bool, 3>& on_map_edge) {
    const auto& tri = in_.triangles[k];
    Polygon whole;
    Vector2d lo = Vector2d::Constant(1e9), hi = -lo;
    for (int c = 0; c < 3; ++c) {
      const auto v = static_cast<std::size_t>(tri[c]);
      whole.add(in_.st[v], in_.kind[v], c);
      lo = lo.cwiseMin(in_.st[v]);
      hi = hi.cwiseMax(in_.st[v]);
    }
    auto cells = [](double a, double b, int n) {
      return std::pair<int, int>(std::clamp(static_cast<int>(std::floor(a * n)), 0, n - 1),
                                 std::clamp(static_cast<int>(std::floor(b * n)), 0, n - 1));
    };
    const auto [i0, i1] = cells(lo.x(), hi.x(), columns_);
    const auto [j0, j1] = cells(lo.y(), hi.y(), across_);
    for (int i = i0; i <= i1; ++i) {
      for (int j = j0; j <= j1; ++j) {
        for (bool upper : {false, true}) {
          const std::array<Vector2d, 3> g = grid_triangle(i, j, upper);
          Polygon piece = whole;
          for (int c = 0; c < 3 && piece.k.size() >= 3; ++c)
            piece = clip(piece, g[c], g[(c + 1) % 3], 1.0);
          if (piece.k.size() >= 3) add_piece(piece, {i, j, upper}, k, on_map_edge);
        }
      }
    }
  }

  std::array<Vector2d, 3> grid_triangle(int i, int j, bool upper) const {
    std::array<Vector2d, 3> corners;
    for (std::size_t c = 0; c < 3; ++c) {
      const auto [di, dj] = kGridTriangle[upper][c];
      corners[c] = {double(i + di) / columns_, double(j + dj) / across_};
    }
    return corners;
  }

  // A convex piece of template triangle k inside one grid triangle: its vertices welded with the
  // drawing's, then fanned (a fan from a corner none of whose triangles is flat, or else from the
  // piece's centre).
  void add_piece(const Polygon& piece, GridLocation where, std::size_t k,
                 const std::array<bool, 3>& on_map_edge) {
    const std::array<Vector2d, 3> g = grid_triangle(where.i, where.j, where.upper);
    std::vector<std::int32_t> v;
    std::vector<int> edge;  // the template triangle's side under piece edge i -> i + 1, or -1
    for (std::size_t i = 0; i < piece.k.size(); ++i) {
      const std::int32_t w = vertex(piece.k[i], piece.kind[i], where, g);
      if (!v.empty() && v.back() == w) continue;
      v.push_back(w);
      edge.push_back(piece.tri_side[i]);
    }
    while (v.size() > 1 && v.back() == v.front()) {
      v.pop_back();
      edge.pop_back();
    }
    if (v.size() < 3) return;
    const Element flag = in_.triangle_flag[k];
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (edge[i] >= 0 && on_map_edge[static_cast<std::size_t>(edge[i])])
        out_.shape.map_edges.push_back({v[i], v[(i + 1) % v.size()]});
    }
    auto area = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
      const auto& st = out_.shape.st;
      return cross(st[static_cast<std::size_t>(b)] - st[static_cast<std::size_t>(a)],
                   st[static_cast<std::size_t>(c)] - st[static_cast<std::size_t>(a)]);
    };
    const std::size_t n = v.size();
    for (std::size_t apex = 0; apex < n; ++apex) {
      bool flat = false;
      for (std::size_t i = 1; i + 1 < n && !flat; ++i)
        flat = area(v[apex], v[(apex + i) % n], v[(apex + i + 1) % n]) <= kFlat;
      if (flat) continue;
      for (std::size_t i = 1; i + 1 < n; ++i)
        add_triangle({v[apex], v[(apex + i) % n], v[(apex + i + 1) % n]}, flag);
      return;
    }
    Vector2d centre = Vector2d::Zero();
    for (std::int32_t w : v) centre += out_.shape.st[static_cast<std::size_t>(w)] / double(n);
    const std::int32_t c = vertex(centre, VertexKind::Interior, where, g);
    for (std::size_t i = 0; i < n; ++i) add_triangle({c, v[i], v[(i + 1) % n]}, flag);
  }

  void add_triangle(const std::array<std::int32_t, 3>& v, Element flag) {
    out_.shape.triangles.push_back(v);
    out_.shape.triangle_flag.push_back(flag);
  }

  // The drawing's vertex at x (welded with an earlier one at the same point), located in grid
  // triangle g.
  std::int32_t vertex(const Vector2d& x, VertexKind kind, GridLocation where,
                      const std::array<Vector2d, 3>& g) {
    if (const std::int32_t v = welded_.find(x, out_.shape.st); v >= 0) {
      if (kind != VertexKind::Interior) out_.shape.kind[static_cast<std::size_t>(v)] = kind;
      return v;
    }
    const auto v = static_cast<std::int32_t>(out_.shape.st.size());
    out_.shape.st.push_back(x);
    out_.shape.kind.push_back(kind);
    const double total = cross(g[1] - g[0], g[2] - g[0]);
    where.weights = {cross(g[1] - x, g[2] - x) / total, cross(g[2] - x, g[0] - x) / total,
                     cross(g[0] - x, g[1] - x) / total};
    out_.location.push_back(where);
    welded_.add(x, v);
    return v;
  }

  // The vertices on the unit square's sides at their parameters (L1 t = 0 and L3 t = 1 by s, L2
  // s = 1 and L4 s = 0 by t).
  void assign_sides() {
    for (std::size_t v = 0; v < out_.shape.st.size(); ++v) {
      Vector2d& st = out_.shape.st[v];
      const auto w = static_cast<std::int32_t>(v);
      // Snapped onto the side exactly: a vertex a hair inside would let the simplifier take the
      // side's edge past it.
      if (std::abs(st.y()) < kOnSquare) st.y() = 0;
      if (std::abs(st.x() - 1) < kOnSquare) st.x() = 1;
      if (std::abs(st.y() - 1) < kOnSquare) st.y() = 1;
      if (std::abs(st.x()) < kOnSquare) st.x() = 0;
      if (st.y() == 0) out_.shape.side[0].push_back({st.x(), w});
      if (st.x() == 1) out_.shape.side[1].push_back({st.y(), w});
      if (st.y() == 1) out_.shape.side[2].push_back({st.x(), w});
      if (st.x() == 0) out_.shape.side[3].push_back({st.y(), w});
    }
    for (auto& side : out_.shape.side) std::sort(side.begin(), side.end());
  }

  static constexpr double kOnSquare = 1e-9, kFlat = 1e-18;
  const Template& in_;
  int columns_, across_;
  Overlay out_;
  Welder welded_;
};

struct TileSides {
  Permutation junction, seam, midpoint;  // the tile across side a, b (= d), c
};

TileSides tile_sides(const RegularSurface& surface, std::size_t tiles) {
  const Connectivity connectivity = build_connectivity(surface.mesh);
  const QuarterTubeAdjacency adjacency = quarter_tube_adjacency(
      surface.mesh, connectivity, surface.mesh.face_attributes.at(kTileAttribute), tiles);
  return {adjacency.a, adjacency.b, adjacency.c};
}

// What quarter tube g carries: `element` times Q, or times c Q when `mirrored`.
struct TileFrame {
  bool mirrored = false;
  Element element = -1;
};

// The frames by a walk from tile 0 (Q itself) over the mesh's adjacency: across the junction
// side Q <-> c Q with the same element; across a seam Q g -> c Q g x^-1 and back by x; across
// the midpoint Q g -> c Q g r with r = y x^-1 and back by r^-1. Error when an adjacency disagrees
// or two tiles of one kind get one element.
std::vector<TileFrame> tile_frames(const TileSides& sides, const ElementWords& words,
                                   const Pairing& pairing) {
  const std::size_t tiles = sides.junction.size();
  const Element x_inverse = words.inverse(pairing.x);
  const Element r = words.multiply(pairing.y, x_inverse);
  const Element r_inverse = words.inverse(r);
  std::vector<TileFrame> frame(tiles);
  frame[0] = {false, 0};
  std::vector<std::int32_t> queue = {0};
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const auto g = static_cast<std::size_t>(queue[k]);
    const TileFrame f = frame[g];
    const std::array<std::pair<const Permutation*, Element>, 3> steps = {
        {{&sides.junction, 0},
         {&sides.seam, f.mirrored ? pairing.x : x_inverse},
         {&sides.midpoint, f.mirrored ? r_inverse : r}}};
    for (const auto& [across, step] : steps) {
      const auto h = static_cast<std::size_t>((*across)[g]);
      const TileFrame expected{!f.mirrored, words.multiply(f.element, step)};
      if (frame[h].element < 0) {
        frame[h] = expected;
        queue.push_back(static_cast<std::int32_t>(h));
      } else if (frame[h].mirrored != expected.mirrored || frame[h].element != expected.element) {
        throw Error("the pairing with " + pairing.target +
                    " does not glue on the surface's quarter tubes (tile " + std::to_string(g) +
                    " and its neighbour " + std::to_string(h) + ")");
      }
    }
  }
  std::set<std::pair<bool, Element>> distinct;
  for (const TileFrame& f : frame) distinct.insert({f.mirrored, f.element});
  if (queue.size() != tiles || distinct.size() != tiles)
    throw Error("the pairing with " + pairing.target +
                " does not give every quarter tube its own element of the source's group");
  return frame;
}

// Whether two quarter tubes' lists of vertices on a side they share are at the same parameters.
bool same_side(const std::vector<std::pair<double, std::int32_t>>& u,
               const std::vector<std::pair<double, std::int32_t>>& v) {
  if (u.size() != v.size()) return false;
  for (std::size_t j = 0; j < u.size(); ++j)
    if (std::abs(u[j].first - v[j].first) > 1e-6) return false;
  return true;
}

// Every flag of M covered once: the pieces' areas over all quarter tubes add up to one flag's
// area on every flag.
bool covers_once(const std::vector<TileFrame>& frames, const ElementWords& words,
                 const std::array<Template, 2>& shapes, double flag_area) {
  std::vector<double> area(words.group().order(), 0.0);
  for (const TileFrame& f : frames) {
    for (const auto& [flag, a] : shapes[f.mirrored ? 1 : 0].pieces)
      area[static_cast<std::size_t>(words.multiply(f.element, flag))] += a;
  }
  return std::all_of(area.begin(), area.end(),
                     [&](double a) { return std::abs(a - flag_area) < 1e-6 * flag_area; });
}

// The surface's point at a grid location: in the plane of the surface's triangle there.
Vector3d grid_point(const Mesh& surface, const QuarterTubeGrid& grid, const GridLocation& at) {
  Vector3d point = Vector3d::Zero();
  for (std::size_t c = 0; c < 3; ++c) {
    const auto [di, dj] = kGridTriangle[at.upper][c];
    point +=
        at.weights[static_cast<Eigen::Index>(c)] * surface.positions[grid.at(at.i + di, at.j + dj)];
  }
  return point;
}

// Each face label's triangles form one open disk: connected, one boundary loop, Euler
// characteristic 1, once the face is cut open along M's edges (`cuts`: a face may lie on both
// sides of an edge; a map of one face lies on both sides of all of them) and every vertex is split
// into one vertex per fan of the face's triangles around it that no cut separates.
bool faces_are_disks(const Mesh& mesh, std::size_t labels,
                     const std::set<std::pair<Index, Index>>& cuts) {
  const std::vector<std::int32_t>& face = mesh.face_attributes.at(kFaceAttribute);
  std::vector<std::vector<Index>> by_label(labels);
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    by_label[static_cast<std::size_t>(face[f])].push_back(static_cast<Index>(f));
  for (const std::vector<Index>& faces : by_label) {
    // Corners k = 3 i + c of the label's i-th triangle; corners at one vertex that share an
    // edge of the label's triangles are one fan.
    DisjointSets fan(3 * faces.size());
    std::map<std::pair<Index, Index>, std::vector<Index>>
        corners_on_edge;  // (v, w) -> corners at v
    for (std::size_t i = 0; i < faces.size(); ++i) {
      for (std::size_t c = 0; c < 3; ++c) {
        const Index v = mesh.face(faces[i])[c];
        for (std::size_t d = 1; d < 3; ++d) {
          const Index w = mesh.face(faces[i])[(c + d) % 3];
          corners_on_edge[{v, w}].push_back(static_cast<Index>(3 * i + c));
        }
      }
    }
    for (const auto& [edge, corners] : corners_on_edge) {
      if (cuts.count({std::min(edge.first, edge.second), std::max(edge.first, edge.second)}) > 0)
        continue;
      for (std::size_t j = 1; j < corners.size(); ++j) {
        fan.join(corners[0], corners[j]);
      }
    }
    Mesh part;
    std::map<Index, Index> index;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      std::array<Index, 3> v{};
      for (std::size_t c = 0; c < 3; ++c) {
        const Index root = static_cast<Index>(fan.find(3 * i + c));
        const auto [it, added] = index.emplace(root, static_cast<Index>(part.vertex_count()));
        if (added) part.add_vertex(mesh.positions[mesh.face(faces[i])[c]]);
        v[c] = it->second;
      }
      part.add_face({v[0], v[1], v[2]});
    }
    try {
      const SurfaceTopology topology = surface_topology(part, build_connectivity(part));
      if (topology.components != 1 || topology.boundary_loops != 1 ||
          topology.euler_characteristic != 1)
        return false;
    } catch (const TopologyError&) {
      return false;
    }
  }
  return true;
}

void check_closed_and_oriented(const Mesh& mesh, MappedMapStats& stats) {
  const Closure c = closure(mesh);
  stats.closed = c.closed;
  stats.oriented = c.oriented;
}

}  // namespace

bool drawn_right(const MappedMapStats& s, const MapFigures& figures) {
  return s.vertices == figures.vertices && s.edges == figures.edges && s.faces == figures.faces &&
         s.faces_are_disks && s.covers_once && s.closed && s.oriented && s.genus == figures.genus;
}

MappedMap map_onto_surface(const FiniteGroup& source, const ElementWords& words,
                           const Pairing& pairing, const RegularSurface& surface,
                           const MappedMapOptions& options, const Progress& progress) {
  const std::size_t tiles = surface.grids.size();
  if (tiles == 0 || tiles * 2 * (source.order() / (2 * tiles)) != source.order())
    throw Error("the pairing with " + pairing.target + " does not fit the surface's " +
                std::to_string(tiles) + " quarter tubes");
  progress.step("template", 0.0);
  TemplateBuilder plain(source, pairing.corners, 1.0), mirrored(source, pairing.mirrored, -1.0);
  const int n = options.subdivisions > 0 ? options.subdivisions : 2;
  const Orbits faces = face_orbits(source);
  const std::array<Template, 2> templates = {plain.build(n), mirrored.build(n)};

  progress.step("quarter tubes", 0.2);
  const TileSides sides = tile_sides(surface, tiles);
  const std::vector<TileFrame> frames = tile_frames(sides, words, pairing);
  // One overlay per template and grid length (a tube's grids grow with its length).
  std::map<std::pair<bool, int>, Overlay> overlays;
  std::vector<const Template*> shape_of(tiles);
  std::vector<const Overlay*> overlay_of(tiles);
  for (std::size_t g = 0; g < tiles; ++g) {
    const QuarterTubeGrid& grid = surface.grids[g];
    const bool m = frames[g].mirrored;
    auto found = overlays.find({m, grid.columns});
    if (found == overlays.end())
      found = overlays
                  .emplace(std::pair(m, grid.columns),
                           OverlayBuilder(templates[m], grid.columns, grid.across).build())
                  .first;
    overlay_of[g] = &found->second;
    shape_of[g] = &found->second.shape;
  }

  // Vertices (tile, template vertex), merged across every side they lie on.
  std::vector<Index> offset(tiles + 1, 0);
  for (std::size_t g = 0; g < tiles; ++g)
    offset[g + 1] = offset[g] + static_cast<Index>(shape_of[g]->st.size());
  DisjointSets same_point(offset[tiles]);
  for (std::size_t g = 0; g < tiles; ++g) {
    const std::array<std::int32_t, 4> across = {sides.seam[g], sides.midpoint[g], sides.seam[g],
                                                sides.junction[g]};
    const Template& mine = *shape_of[g];
    for (std::size_t i = 0; i < 4; ++i) {
      const auto h = static_cast<std::size_t>(across[i]);
      const Template& theirs = *shape_of[h];
      if (!same_side(mine.side[i], theirs.side[i]))
        throw Error("the pairing with " + pairing.target + ": quarter tubes " + std::to_string(g) +
                    " and " + std::to_string(h) + " disagree on side L" + std::to_string(i + 1));
      for (std::size_t j = 0; j < mine.side[i].size(); ++j) {
        same_point.join(offset[g] + static_cast<Index>(mine.side[i][j].second),
                        offset[h] + static_cast<Index>(theirs.side[i][j].second));
      }
    }
  }
  MappedMap out;
  Mesh& mesh = out.mesh;
  std::vector<Index> vertex(offset[tiles], kNoIndex);
  std::set<Index> map_vertices, midpoints;
  for (std::size_t g = 0; g < tiles; ++g) {
    const Overlay& overlay = *overlay_of[g];
    const Template& shape = overlay.shape;
    for (std::size_t v = 0; v < shape.st.size(); ++v) {
      const Index root = static_cast<Index>(same_point.find(offset[g] + static_cast<Index>(v)));
      if (vertex[root] == kNoIndex)
        vertex[root] =
            mesh.add_vertex(grid_point(surface.mesh, surface.grids[g], overlay.location[v]));
      vertex[offset[g] + v] = vertex[root];
      if (shape.kind[v] == VertexKind::MapVertex) map_vertices.insert(vertex[root]);
      if (shape.kind[v] == VertexKind::EdgeMidpoint) midpoints.insert(vertex[root]);
    }
  }
  progress.step("faces", 0.5);
  std::vector<std::int32_t> face_label, tile_label;
  // The faces at one place of one template, over all quarter tubes of that kind, are one orbit of
  // the elements those tubes carry: the first face seen at each place stands for the others.
  DisjointSets orbit_sets(faces.count);
  std::map<std::pair<bool, Element>, Index> first_at_place;
  std::set<std::pair<Index, Index>> segments;
  for (std::size_t g = 0; g < tiles; ++g) {
    const Template& shape = *shape_of[g];
    const bool flip = !surface.grids[g].counterclockwise;
    auto at = [&](std::int32_t v) { return vertex[offset[g] + static_cast<Index>(v)]; };
    for (std::size_t k = 0; k < shape.triangles.size(); ++k) {
      const auto& t = shape.triangles[k];
      if (flip)
        mesh.add_face({at(t[0]), at(t[2]), at(t[1])});
      else
        mesh.add_face({at(t[0]), at(t[1]), at(t[2])});
      const Element flag = words.multiply(frames[g].element, shape.triangle_flag[k]);
      const std::int32_t face = faces.label[static_cast<std::size_t>(flag)];
      face_label.push_back(face);
      tile_label.push_back(static_cast<std::int32_t>(g));
      const auto [place, first] = first_at_place.emplace(
          std::pair(frames[g].mirrored, shape.triangle_flag[k]), static_cast<Index>(face));
      if (!first) {
        orbit_sets.join(place->second, static_cast<Index>(face));
      }
    }
    for (const auto& [u, v] : shape.map_edges)
      segments.insert({std::min(at(u), at(v)), std::max(at(u), at(v))});
  }
  std::vector<std::int32_t> orbit_of_root(faces.count, -1), orbit_label;
  std::int32_t orbits = 0;
  for (std::int32_t face : face_label) {
    std::int32_t& orbit = orbit_of_root[orbit_sets.find(static_cast<std::size_t>(face))];
    if (orbit < 0) orbit = orbits++;
    orbit_label.push_back(orbit);
  }
  mesh.face_attributes[kFaceAttribute] = std::move(face_label);
  mesh.face_attributes[kOrbitAttribute] = std::move(orbit_label);
  mesh.face_attributes[kTileAttribute] = std::move(tile_label);
  for (const auto& [a, b] : segments) out.edge_segments.push_back({a, b});

  progress.step("checks", 0.7);
  MappedMapStats& stats = out.stats;
  stats.subdivisions = n;
  stats.mesh_vertices = mesh.vertex_count();
  stats.mesh_faces = mesh.face_count();
  stats.vertices = map_vertices.size();
  stats.edges = midpoints.size();
  const FundamentalTriangle base = fundamental_triangle(source.p, source.q);
  stats.covers_once =
      covers_once(frames, words, templates,
                  polygon_area(base.geometry, {base.corners.begin(), base.corners.end()}));
  const auto& labels = mesh.face_attributes.at(kFaceAttribute);
  stats.faces = std::set<std::int32_t>(labels.begin(), labels.end()).size();
  stats.face_orbits = static_cast<std::size_t>(orbits);
  stats.faces_are_disks = faces_are_disks(mesh, faces.count, segments);
  check_closed_and_oriented(mesh, stats);
  if (stats.closed && stats.oriented)
    stats.genus = surface_topology(mesh, build_connectivity(mesh)).genus;
  if (options.find_self_intersections) {
    stats.self_intersections = find_self_intersections(mesh, progress).triangle_pairs;
    stats.self_intersections_searched = true;
  }
  return out;
}

}  // namespace tessera::regmap
