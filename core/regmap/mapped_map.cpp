#include "regmap/mapped_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <utility>

#include <Eigen/LU>
#include <Eigen/SparseLU>

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

class TemplateBuilder {
 public:
  // `quad` in the cover, `sign` +1 when it is counterclockwise, -1 when clockwise.
  TemplateBuilder(const FiniteGroup& source, const std::array<Point, 4>& quad, double sign)
      : cover_(source), sign_(sign) {
    const Geometry g = cover_.geometry();
    Complex centre = 0;
    for (const Point& c : quad) centre += to_plane(c) / 4.0;
    recentre_ = inverse(g, translation_to(g, centre));
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
    const long long i = std::llround(x.x() / kCell), j = std::llround(x.y() / kCell);
    for (long long di = -1; di <= 1; ++di) {
      for (long long dj = -1; dj <= 1; ++dj) {
        const auto found = welded_.find({i + di, j + dj});
        if (found == welded_.end()) continue;
        for (std::int32_t v : found->second) {
          if ((klein_[static_cast<std::size_t>(v)] - x).norm() < kWeld) {
            if (kind != VertexKind::Interior) result_.kind[static_cast<std::size_t>(v)] = kind;
            return v;
          }
        }
      }
    }
    const auto v = static_cast<std::int32_t>(klein_.size());
    klein_.push_back(x);
    welded_[{i, j}].push_back(v);
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

  static constexpr double kCell = 1e-6, kWeld = 1e-9;
  Cover cover_;
  double sign_;
  Isometry recentre_;
  std::array<Point, 4> corners_;
  std::array<Vector2d, 4> klein_corners_;
  std::vector<std::pair<Element, Polygon>> pieces_;
  std::vector<Vector2d> klein_;
  std::map<std::pair<long long, long long>, std::vector<std::int32_t>> welded_;
  Template result_;
};

// Splits the template's edges at their (s, t) midpoints until none is longer than a cell of the
// quarter tube's grid (columns x across over the unit square), so that its triangles follow the
// surface as closely as the grid does. Triangles with a long edge also split their longest
// interior edge (longest-edge bisection keeps their shape); a side's edges split only by their
// own length, so both templates that share the side split it alike.
void refine_to_grid(Template& shape, int columns, int across) {
  using Edge = std::pair<std::int32_t, std::int32_t>;
  auto key = [](std::int32_t u, std::int32_t v) { return Edge(std::min(u, v), std::max(u, v)); };
  auto length = [&](std::int32_t u, std::int32_t v) {
    const Vector2d d =
        shape.st[static_cast<std::size_t>(u)] - shape.st[static_cast<std::size_t>(v)];
    return std::hypot(d.x() * columns, d.y() * across);
  };
  // Longer than a cell, with room for rounding: an edge of exactly one cell stays.
  constexpr double kLongest = 1.0 + 1e-6;
  std::vector<std::uint8_t> on_sides(shape.st.size(), 0);
  for (std::size_t i = 0; i < 4; ++i)
    for (const auto& [p, v] : shape.side[i]) on_sides[static_cast<std::size_t>(v)] |= 1u << i;
  auto on_side = [&](std::int32_t u, std::int32_t v) {
    return on_sides[static_cast<std::size_t>(u)] & on_sides[static_cast<std::size_t>(v)];
  };
  // First the grid's own nodes on the sides (so that the sides follow the grid's boundary), then
  // midpoints of long edges.
  for (bool grid_nodes = true;;) {
    std::map<Edge, std::pair<Vector2d, std::int32_t>> split;  // the new point, its vertex
    for (const auto& tri : shape.triangles) {
      int longest = -1;
      bool any = false;
      for (int c = 0; c < 3; ++c) {
        const std::int32_t u = tri[c], v = tri[(c + 1) % 3];
        const Vector2d& a = shape.st[static_cast<std::size_t>(u)];
        const Vector2d& b = shape.st[static_cast<std::size_t>(v)];
        if (grid_nodes) {
          const std::uint8_t sides = on_side(u, v);
          if (sides == 0) continue;
          const int axis = (sides & 0b0101) != 0 ? 0 : 1;  // L1, L3 run along s; L2, L4 along t
          const int cells = axis == 0 ? columns : across;
          const double lo = std::min(a[axis], b[axis]) * cells,
                       hi = std::max(a[axis], b[axis]) * cells;
          const double node = std::floor(lo + 1e-6) + 1;
          if (node < hi - 1e-6) {
            Vector2d at = a;
            at[axis] = node / cells;
            split[key(u, v)] = {at, -1};
          }
          continue;
        }
        if (length(u, v) > kLongest) {
          any = true;
          split[key(u, v)] = {0.5 * (a + b), -1};
        }
        if (on_side(u, v) == 0 &&
            (longest < 0 || length(u, v) > length(tri[longest], tri[(longest + 1) % 3])))
          longest = c;
      }
      if (any && longest >= 0) {
        const std::int32_t u = tri[longest], v = tri[(longest + 1) % 3];
        split[key(u, v)] = {
            0.5 * (shape.st[static_cast<std::size_t>(u)] + shape.st[static_cast<std::size_t>(v)]),
            -1};
      }
    }
    if (split.empty()) {
      if (!grid_nodes) return;
      grid_nodes = false;
      continue;
    }
    for (auto& [edge, point] : split) {
      const auto u = static_cast<std::size_t>(edge.first),
                 v = static_cast<std::size_t>(edge.second);
      const Vector2d st = point.first;
      point.second = static_cast<std::int32_t>(shape.st.size());
      shape.st.push_back(st);
      shape.kind.push_back(VertexKind::Interior);
      const std::uint8_t sides = on_sides[u] & on_sides[v];
      on_sides.push_back(sides);
      for (std::size_t i = 0; i < 4; ++i)
        if (sides & (1u << i))
          shape.side[i].push_back({i % 2 == 0 ? st.x() : st.y(), point.second});
    }
    auto middle = [&](std::int32_t u, std::int32_t v) {
      const auto found = split.find(key(u, v));
      return found == split.end() ? -1 : found->second.second;
    };
    std::vector<std::array<std::int32_t, 3>> triangles;
    std::vector<Element> flags;
    auto add = [&](std::int32_t a, std::int32_t b, std::int32_t c, Element flag) {
      triangles.push_back({a, b, c});
      flags.push_back(flag);
    };
    for (std::size_t k = 0; k < shape.triangles.size(); ++k) {
      const auto& t = shape.triangles[k];
      const Element f = shape.triangle_flag[k];
      const std::array<std::int32_t, 3> m = {middle(t[0], t[1]), middle(t[1], t[2]),
                                             middle(t[2], t[0])};
      const int count = (m[0] >= 0) + (m[1] >= 0) + (m[2] >= 0);
      if (count == 0) {
        add(t[0], t[1], t[2], f);
      } else if (count == 3) {
        add(t[0], m[0], m[2], f);
        add(m[0], t[1], m[1], f);
        add(m[2], m[1], t[2], f);
        add(m[0], m[1], m[2], f);
      } else if (count == 1) {
        const int c = m[0] >= 0 ? 0 : m[1] >= 0 ? 1 : 2;
        const std::int32_t a = t[c], b = t[(c + 1) % 3], o = t[(c + 2) % 3];
        add(a, m[c], o, f);
        add(m[c], b, o, f);
      } else {
        // The unsplit edge a -> o; the split ones o -> b and b -> a.
        const int u = m[0] < 0 ? 0 : m[1] < 0 ? 1 : 2;
        const std::int32_t a = t[u], o = t[(u + 1) % 3], b = t[(u + 2) % 3];
        const std::int32_t ob = m[(u + 1) % 3], ba = m[(u + 2) % 3];
        add(ob, b, ba, f);
        if (length(a, ob) < length(o, ba)) {
          add(a, o, ob, f);
          add(a, ob, ba, f);
        } else {
          add(a, o, ba, f);
          add(o, ob, ba, f);
        }
      }
    }
    shape.triangles = std::move(triangles);
    shape.triangle_flag = std::move(flags);
    std::vector<std::array<std::int32_t, 2>> edges;
    for (const auto& [u, v] : shape.map_edges) {
      const std::int32_t mid = middle(u, v);
      if (mid < 0) {
        edges.push_back({u, v});
      } else {
        edges.push_back({u, mid});
        edges.push_back({mid, v});
      }
    }
    shape.map_edges = std::move(edges);
  }
}

// Lawson's flips in the grid's metric ((s, t) scaled by columns, across): every edge that is not
// on a side, not on one of M's edges and not between two of M's faces is flipped while the two
// angles facing it sum to more than pi (and its quadrilateral is convex), which removes the
// slivers the cut pieces leave (their 3D chords cross the surface's other sheets).
void flip_to_delaunay(Template& shape, int columns, int across,
                      const std::vector<std::int32_t>& face_of_flag) {
  using Edge = std::pair<std::int32_t, std::int32_t>;
  auto key = [](std::int32_t u, std::int32_t v) { return Edge(std::min(u, v), std::max(u, v)); };
  auto point = [&](std::int32_t v) {
    const Vector2d& st = shape.st[static_cast<std::size_t>(v)];
    return Vector2d(st.x() * columns, st.y() * across);
  };
  std::set<Edge> fixed;
  for (const auto& [u, v] : shape.map_edges) fixed.insert(key(u, v));
  std::vector<std::uint8_t> on_sides(shape.st.size(), 0);
  for (std::size_t i = 0; i < 4; ++i)
    for (const auto& [p, v] : shape.side[i]) on_sides[static_cast<std::size_t>(v)] |= 1u << i;
  auto face = [&](std::size_t t) {
    return face_of_flag[static_cast<std::size_t>(shape.triangle_flag[t])];
  };
  // The angle at corner c of triangle t.
  auto angle = [&](std::size_t t, int c) {
    const auto& tri = shape.triangles[t];
    const Vector2d u = point(tri[(c + 1) % 3]) - point(tri[c]);
    const Vector2d w = point(tri[(c + 2) % 3]) - point(tri[c]);
    return std::atan2(std::abs(cross(u, w)), u.dot(w));
  };
  for (int pass = 0; pass < 100; ++pass) {
    std::map<Edge, std::vector<std::pair<std::size_t, int>>> sides_of;  // (triangle, corner)
    for (std::size_t t = 0; t < shape.triangles.size(); ++t)
      for (int c = 0; c < 3; ++c)
        sides_of[key(shape.triangles[t][c], shape.triangles[t][(c + 1) % 3])].push_back({t, c});
    std::vector<bool> touched(shape.triangles.size(), false);
    int flips = 0;
    for (const auto& [edge, users] : sides_of) {
      if (users.size() != 2 || fixed.count(edge) > 0) continue;
      if ((on_sides[static_cast<std::size_t>(edge.first)] &
           on_sides[static_cast<std::size_t>(edge.second)]) != 0)
        continue;
      const auto [t0, c0] = users[0];
      const auto [t1, c1] = users[1];
      if (touched[t0] || touched[t1] || face(t0) != face(t1)) continue;
      // Triangle t0 = (a, b, o0) with the edge a -> b at corner c0; t1 has it as b -> a.
      const std::int32_t a = shape.triangles[t0][c0], b = shape.triangles[t0][(c0 + 1) % 3];
      const std::int32_t o0 = shape.triangles[t0][(c0 + 2) % 3];
      const std::int32_t o1 = shape.triangles[t1][(c1 + 2) % 3];
      if (angle(t0, (c0 + 2) % 3) + angle(t1, (c1 + 2) % 3) <= std::numbers::pi + 1e-12) continue;
      // The new triangles (a, o1, o0) and (b, o0, o1) must both turn the old way.
      const double turn = cross(point(b) - point(a), point(o0) - point(a));
      const double n0 = cross(point(o1) - point(a), point(o0) - point(a));
      const double n1 = cross(point(o0) - point(b), point(o1) - point(b));
      if (n0 * turn <= 0 || n1 * turn <= 0) continue;
      const Element f0 = shape.triangle_flag[t0];
      shape.triangles[t0] = {a, o1, o0};
      shape.triangles[t1] = {b, o0, o1};
      shape.triangle_flag[t1] = f0;
      touched[t0] = touched[t1] = true;
      ++flips;
    }
    if (flips == 0) return;
  }
}

// Moves every free vertex (inside one of M's faces, off the sides and off M's edges) to the mean
// of its neighbours, a few times, in the grid's metric: the slivers the cut pieces leave become
// better shaped triangles. A move that would turn a triangle over is not made.
void smooth(Template& shape, const std::vector<std::int32_t>& face_of_flag) {
  const std::size_t nv = shape.st.size();
  std::vector<bool> free(nv, true);
  for (const auto& side : shape.side)
    for (const auto& [p, v] : side) free[static_cast<std::size_t>(v)] = false;
  for (const auto& [u, v] : shape.map_edges)
    free[static_cast<std::size_t>(u)] = free[static_cast<std::size_t>(v)] = false;
  std::vector<std::int32_t> face(nv, -1);
  std::vector<std::vector<std::size_t>> around(nv);
  for (std::size_t t = 0; t < shape.triangles.size(); ++t) {
    const std::int32_t f = face_of_flag[static_cast<std::size_t>(shape.triangle_flag[t])];
    for (std::int32_t v : shape.triangles[t]) {
      const auto i = static_cast<std::size_t>(v);
      if (face[i] >= 0 && face[i] != f) free[i] = false;
      face[i] = f;
      around[i].push_back(t);
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (shape.kind[v] != VertexKind::Interior) free[v] = false;
  auto turns_left = [&](std::size_t t) {
    const auto& tri = shape.triangles[t];
    const Vector2d& a = shape.st[static_cast<std::size_t>(tri[0])];
    return cross(shape.st[static_cast<std::size_t>(tri[1])] - a,
                 shape.st[static_cast<std::size_t>(tri[2])] - a) > 0;
  };
  for (int pass = 0; pass < 4; ++pass) {
    for (std::size_t v = 0; v < nv; ++v) {
      if (!free[v] || around[v].empty()) continue;
      Vector2d sum = Vector2d::Zero();
      double count = 0;
      for (std::size_t t : around[v]) {
        for (std::int32_t w : shape.triangles[t]) {
          if (static_cast<std::size_t>(w) == v) continue;
          sum += shape.st[static_cast<std::size_t>(w)];
          count += 1;
        }
      }
      const Vector2d old = shape.st[v];
      shape.st[v] = sum / count;
      for (std::size_t t : around[v]) {
        if (!turns_left(t)) {
          shape.st[v] = old;
          break;
        }
      }
    }
  }
}

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

Index find_root(std::vector<Index>& parent, Index v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// The point of tile `grid` at (s, t): bilinear in the grid's cell.
Vector3d grid_point(const Mesh& surface, const QuarterTubeGrid& grid, const Vector2d& st) {
  const double u = st.x() * grid.columns, v = st.y() * grid.across;
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, grid.columns - 1);
  const int j = std::clamp(static_cast<int>(std::floor(v)), 0, grid.across - 1);
  const double fu = u - i, fv = v - j;
  auto p = [&](int di, int dj) { return surface.positions[grid.at(i + di, j + dj)]; };
  return (1 - fu) * (1 - fv) * p(0, 0) + fu * (1 - fv) * p(1, 0) + fu * fv * p(1, 1) +
         (1 - fu) * fv * p(0, 1);
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
    std::vector<Index> fan(3 * faces.size());
    std::iota(fan.begin(), fan.end(), Index{0});
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
        const Index a = find_root(fan, corners[0]), b = find_root(fan, corners[j]);
        if (a != b) fan[std::max(a, b)] = std::min(a, b);
      }
    }
    Mesh part;
    std::map<Index, Index> index;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      std::array<Index, 3> v{};
      for (std::size_t c = 0; c < 3; ++c) {
        const Index root = find_root(fan, static_cast<Index>(3 * i + c));
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

MappedMap map_onto_surface(const FiniteGroup& source, const ElementWords& words,
                           const Pairing& pairing, const RegularSurface& surface,
                           const MappedMapOptions& options, const Progress& progress) {
  const std::size_t tiles = surface.grids.size();
  if (tiles == 0 || tiles * 2 * (source.order() / (2 * tiles)) != source.order())
    throw Error("the pairing with " + pairing.target + " does not fit the surface's " +
                std::to_string(tiles) + " quarter tubes");
  progress.step("template", 0.0);
  TemplateBuilder plain(source, pairing.corners, 1.0), mirrored(source, pairing.mirrored, -1.0);
  const QuarterTubeGrid& first = surface.grids[0];
  const int n = options.subdivisions > 0 ? options.subdivisions : 2;
  const Orbits faces = face_orbits(source);
  std::array<Template, 2> shapes = {plain.build(n), mirrored.build(n)};
  for (Template& shape : shapes) {
    refine_to_grid(shape, first.columns, first.across);
    flip_to_delaunay(shape, first.columns, first.across, faces.label);
    smooth(shape, faces.label);
    flip_to_delaunay(shape, first.columns, first.across, faces.label);
    for (auto& side : shape.side) std::sort(side.begin(), side.end());
  }
  for (std::size_t i = 0; i < 4; ++i) {
    const auto &u = shapes[0].side[i], &v = shapes[1].side[i];
    bool same = u.size() == v.size();
    for (std::size_t j = 0; same && j < u.size(); ++j)
      same = std::abs(u[j].first - v[j].first) < 1e-6;
    if (!same)
      throw Error("the pairing with " + pairing.target + ": Q and c Q disagree on side L" +
                  std::to_string(i + 1));
  }

  progress.step("quarter tubes", 0.2);
  const TileSides sides = tile_sides(surface, tiles);
  const std::vector<TileFrame> frames = tile_frames(sides, words, pairing);

  // Vertices (tile, template vertex), merged across every side they lie on.
  std::vector<Index> offset(tiles + 1, 0);
  for (std::size_t g = 0; g < tiles; ++g)
    offset[g + 1] = offset[g] + static_cast<Index>(shapes[frames[g].mirrored].st.size());
  std::vector<Index> parent(offset[tiles]);
  std::iota(parent.begin(), parent.end(), Index{0});
  for (std::size_t g = 0; g < tiles; ++g) {
    const std::array<std::int32_t, 4> across = {sides.seam[g], sides.midpoint[g], sides.seam[g],
                                                sides.junction[g]};
    const Template& mine = shapes[frames[g].mirrored];
    for (std::size_t i = 0; i < 4; ++i) {
      const auto h = static_cast<std::size_t>(across[i]);
      const Template& theirs = shapes[frames[h].mirrored];
      for (std::size_t j = 0; j < mine.side[i].size(); ++j) {
        const Index u = find_root(parent, offset[g] + static_cast<Index>(mine.side[i][j].second));
        const Index v = find_root(parent, offset[h] + static_cast<Index>(theirs.side[i][j].second));
        if (u != v) parent[std::max(u, v)] = std::min(u, v);
      }
    }
  }
  MappedMap out;
  Mesh& mesh = out.mesh;
  std::vector<Index> vertex(offset[tiles], kNoIndex);
  std::set<Index> map_vertices, midpoints;
  for (std::size_t g = 0; g < tiles; ++g) {
    const Template& shape = shapes[frames[g].mirrored];
    for (std::size_t v = 0; v < shape.st.size(); ++v) {
      const Index root = find_root(parent, offset[g] + static_cast<Index>(v));
      if (vertex[root] == kNoIndex)
        vertex[root] = mesh.add_vertex(grid_point(surface.mesh, surface.grids[g], shape.st[v]));
      vertex[offset[g] + v] = vertex[root];
      if (shape.kind[v] == VertexKind::MapVertex) map_vertices.insert(vertex[root]);
      if (shape.kind[v] == VertexKind::EdgeMidpoint) midpoints.insert(vertex[root]);
    }
  }
  progress.step("faces", 0.5);
  std::vector<std::int32_t> face_label, tile_label;
  std::set<std::pair<Index, Index>> segments;
  for (std::size_t g = 0; g < tiles; ++g) {
    const Template& shape = shapes[frames[g].mirrored];
    const bool flip = !surface.grids[g].counterclockwise;
    auto at = [&](std::int32_t v) { return vertex[offset[g] + static_cast<Index>(v)]; };
    for (std::size_t k = 0; k < shape.triangles.size(); ++k) {
      const auto& t = shape.triangles[k];
      if (flip)
        mesh.add_face({at(t[0]), at(t[2]), at(t[1])});
      else
        mesh.add_face({at(t[0]), at(t[1]), at(t[2])});
      const Element flag = words.multiply(frames[g].element, shape.triangle_flag[k]);
      face_label.push_back(faces.label[static_cast<std::size_t>(flag)]);
      tile_label.push_back(static_cast<std::int32_t>(g));
    }
    for (const auto& [u, v] : shape.map_edges)
      segments.insert({std::min(at(u), at(v)), std::max(at(u), at(v))});
  }
  mesh.face_attributes[kFaceAttribute] = std::move(face_label);
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
      covers_once(frames, words, shapes,
                  polygon_area(base.geometry, {base.corners.begin(), base.corners.end()}));
  const auto& labels = mesh.face_attributes.at(kFaceAttribute);
  stats.faces = std::set<std::int32_t>(labels.begin(), labels.end()).size();
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
