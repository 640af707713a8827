#include "regmap/mapped_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <utility>

#include <Eigen/LU>

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

constexpr double kOnSide = 1e-7;  // (s, t) this close to 0 or 1 lie on hQ's side

// The Klein model's point of a Poincare disk point: geodesics become chords.
Vector2d klein(const Point& p) {
  const Complex z = to_plane(p);
  const double scale = 2.0 / (1.0 + std::norm(z));
  return {scale * z.real(), scale * z.imag()};
}

// (s, t) with (1-s)(1-t) q0 + s(1-t) q1 + s t q2 + (1-s) t q3 = x, by Newton's method from the
// centre (the quadrilateral is convex, so the map is one to one on the square).
Vector2d inverse_bilinear(const std::array<Vector2d, 4>& q, const Vector2d& x) {
  Vector2d st(0.5, 0.5);
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double s = st.x(), t = st.y();
    const Vector2d f =
        (1 - s) * (1 - t) * q[0] + s * (1 - t) * q[1] + s * t * q[2] + (1 - s) * t * q[3] - x;
    const Vector2d ds = (1 - t) * (q[1] - q[0]) + t * (q[2] - q[3]);
    const Vector2d dt = (1 - s) * (q[3] - q[0]) + s * (q[2] - q[1]);
    Eigen::Matrix2d jacobian;
    jacobian << ds, dt;
    const Vector2d step = jacobian.inverse() * f;
    st -= step;
    if (step.norm() < 1e-15) break;
  }
  for (int k = 0; k < 2; ++k) {
    if (std::abs(st[k]) < kOnSide) st[k] = 0.0;
    if (std::abs(st[k] - 1.0) < kOnSide) st[k] = 1.0;
  }
  return st;
}

enum class VertexKind { Interior, MapVertex, EdgeMidpoint };

// hQ's flag triangles, subdivided and welded: one triangulated disk in (s, t).
struct Template {
  std::vector<Vector2d> st;  // per vertex
  std::vector<VertexKind> kind;
  std::vector<std::array<std::int32_t, 3>> triangles;  // counterclockwise in (s, t)
  std::vector<std::int32_t> triangle_flag;             // index into the pairing's flags
  std::vector<std::array<std::int32_t, 2>> map_edges;  // template edges along N-O sides
};

class TemplateBuilder {
 public:
  TemplateBuilder(const Pairing& pairing, const FundamentalTriangle& base, double spacing)
      : pairing_(pairing), base_(base), cell_(spacing / 4) {
    // hQ moved so that its corners' centre is at the origin: Klein coordinates are best there.
    const Geometry g = base.geometry;
    Complex centre = 0;
    for (const Point& c : pairing.corners) centre += to_plane(c) / 4.0;
    recentre_ = inverse(g, translation_to(g, centre));
    for (std::size_t i = 0; i < 4; ++i)
      corners_[i] = klein(apply(g, recentre_, pairing.corners[i]));
  }

  Template build(int n) {
    for (std::size_t f = 0; f < pairing_.flags.size(); ++f) add_flag(f, n);
    return std::move(result_);
  }

 private:
  Vector2d corner(const CoverTriangle& t, Corner c) const {
    const Geometry g = base_.geometry;
    return klein(apply(g, recentre_, apply(g, t.placement, base_.corners[c])));
  }

  // The template vertex at Klein point x (welded with an earlier one within a cell).
  std::int32_t vertex(const Vector2d& x, VertexKind kind) {
    const long i = std::lround(x.x() / cell_), j = std::lround(x.y() / cell_);
    for (long di = -1; di <= 1; ++di) {
      for (long dj = -1; dj <= 1; ++dj) {
        const auto found = welded_.find({i + di, j + dj});
        if (found == welded_.end()) continue;
        for (std::int32_t v : found->second) {
          if ((klein_[static_cast<std::size_t>(v)] - x).norm() < cell_) return v;
        }
      }
    }
    const auto v = static_cast<std::int32_t>(klein_.size());
    klein_.push_back(x);
    welded_[{i, j}].push_back(v);
    result_.st.push_back(inverse_bilinear(corners_, x));
    result_.kind.push_back(kind);
    return v;
  }

  // Flag f's triangle M N O, n x n: grid point (i, j) = M + i/n (N - M) + j/n (O - M).
  void add_flag(std::size_t f, int n) {
    const CoverTriangle& t = pairing_.flags[f];
    const Vector2d m = corner(t, kM), nn = corner(t, kN), o = corner(t, kO);
    std::vector<std::vector<std::int32_t>> grid(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        VertexKind kind = VertexKind::Interior;
        if (i == n) kind = VertexKind::MapVertex;
        if (j == n) kind = VertexKind::EdgeMidpoint;
        const Vector2d x = m + (double(i) / n) * (nn - m) + (double(j) / n) * (o - m);
        grid[static_cast<std::size_t>(i)].push_back(vertex(x, kind));
      }
    }
    auto at = [&](int i, int j) {
      return grid[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; i + j < n; ++j) {
        add_triangle({at(i, j), at(i + 1, j), at(i, j + 1)}, f);
        if (i + j + 2 <= n) add_triangle({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, f);
      }
    }
    // The N-O side: i + j = n.
    for (int i = n; i > 0; --i) result_.map_edges.push_back({at(i, n - i), at(i - 1, n - i + 1)});
  }

  void add_triangle(std::array<std::int32_t, 3> v, std::size_t flag) {
    const auto& st = result_.st;
    const Vector2d e1 = st[static_cast<std::size_t>(v[1])] - st[static_cast<std::size_t>(v[0])];
    const Vector2d e2 = st[static_cast<std::size_t>(v[2])] - st[static_cast<std::size_t>(v[0])];
    if (e1.x() * e2.y() - e1.y() * e2.x() < 0) std::swap(v[1], v[2]);
    result_.triangles.push_back(v);
    result_.triangle_flag.push_back(static_cast<std::int32_t>(flag));
  }

  const Pairing& pairing_;
  const FundamentalTriangle& base_;
  double cell_;
  Isometry recentre_;
  std::array<Vector2d, 4> corners_;
  std::vector<Vector2d> klein_;
  std::map<std::pair<long, long>, std::vector<std::int32_t>> welded_;
  Template result_;
};

// The shortest Klein-model side of a flag triangle of hQ, over n: the template's spacing.
double template_spacing(const Pairing& pairing, const FundamentalTriangle& base, int n) {
  double shortest = 1e300;
  const Geometry g = base.geometry;
  for (const CoverTriangle& t : pairing.flags) {
    for (Side side : kSides) {
      const auto [u, v] = side_corners(side);
      const Vector2d a = klein(apply(g, t.placement, base.corners[u]));
      const Vector2d b = klein(apply(g, t.placement, base.corners[v]));
      shortest = std::min(shortest, (a - b).norm());
    }
  }
  return shortest / n;
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

// phi(tile) by a walk from tile 0 (phi = 1); Error when an adjacency disagrees or two tiles get
// one element.
std::vector<Element> tile_elements(const TileSides& sides, const ElementWords& words,
                                   const Pairing& pairing) {
  const std::size_t tiles = sides.junction.size();
  std::vector<Element> phi(tiles, -1);
  phi[0] = 0;
  std::vector<std::int32_t> queue = {0};
  const std::array<std::pair<const Permutation*, Element>, 3> steps = {
      {{&sides.junction, pairing.c}, {&sides.seam, pairing.a}, {&sides.midpoint, pairing.b}}};
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const auto g = static_cast<std::size_t>(queue[k]);
    for (const auto& [across, x] : steps) {
      const auto h = static_cast<std::size_t>((*across)[g]);
      const Element expected = words.multiply(phi[g], x);
      if (phi[h] < 0) {
        phi[h] = expected;
        queue.push_back(static_cast<std::int32_t>(h));
      } else if (phi[h] != expected) {
        throw Error("the pairing with " + pairing.target +
                    " does not glue on the surface's quarter tubes (tile " + std::to_string(g) +
                    " and its neighbour " + std::to_string(h) + ")");
      }
    }
  }
  if (queue.size() != tiles || std::set<Element>(phi.begin(), phi.end()).size() != tiles)
    throw Error("the pairing with " + pairing.target +
                " does not give every quarter tube its own element of the source's group");
  return phi;
}

// Every flag of M exactly once among {phi(g) f}.
bool covers_once(const std::vector<Element>& phi, const ElementWords& words,
                 const Pairing& pairing) {
  std::vector<int> hits(words.group().order(), 0);
  for (Element g : phi) {
    for (const CoverTriangle& f : pairing.flags)
      ++hits[static_cast<std::size_t>(words.multiply(g, f.element))];
  }
  return std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; });
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

// Each face label's triangles form one disk: connected, one boundary loop, Euler characteristic 1.
bool faces_are_disks(const Mesh& mesh, std::size_t labels) {
  const std::vector<std::int32_t>& face = mesh.face_attributes.at(kFaceAttribute);
  std::vector<std::vector<Index>> by_label(labels);
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    by_label[static_cast<std::size_t>(face[f])].push_back(static_cast<Index>(f));
  for (const std::vector<Index>& faces : by_label) {
    Mesh part;
    std::map<Index, Index> index;
    for (Index f : faces) {
      std::array<Index, 3> v{};
      for (std::size_t c = 0; c < 3; ++c) {
        const Index old = mesh.face(f)[c];
        const auto [it, added] = index.emplace(old, static_cast<Index>(part.vertex_count()));
        if (added) part.add_vertex(mesh.positions[old]);
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
  if (tiles == 0 || pairing.flags.empty() || tiles * pairing.flags.size() != source.order())
    throw Error("the pairing with " + pairing.target + " does not fit the surface's " +
                std::to_string(tiles) + " quarter tubes");
  progress.step("template", 0.0);
  const QuarterTubeGrid& first = surface.grids[0];
  const double cells = double(first.columns) * first.across / double(pairing.flags.size());
  const int n = options.subdivisions > 0
                    ? options.subdivisions
                    : std::clamp(static_cast<int>(std::ceil(std::sqrt(2.0 * cells))), 2, 24);
  const FundamentalTriangle base = fundamental_triangle(source.p, source.q);
  const Template shape =
      TemplateBuilder(pairing, base, template_spacing(pairing, base, n)).build(n);

  progress.step("quarter tubes", 0.2);
  const TileSides sides = tile_sides(surface, tiles);
  const std::vector<Element> phi = tile_elements(sides, words, pairing);

  // Vertices (tile, template vertex), merged across every side they lie on.
  const std::size_t nv = shape.st.size();
  std::vector<Index> parent(tiles * nv);
  std::iota(parent.begin(), parent.end(), Index{0});
  auto unite = [&](std::size_t g, std::size_t h, std::size_t v) {
    const Index a = find_root(parent, static_cast<Index>(g * nv + v));
    const Index b = find_root(parent, static_cast<Index>(h * nv + v));
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  for (std::size_t g = 0; g < tiles; ++g) {
    for (std::size_t v = 0; v < nv; ++v) {
      const Vector2d& st = shape.st[v];
      if (st.x() == 0.0) unite(g, static_cast<std::size_t>(sides.junction[g]), v);
      if (st.x() == 1.0) unite(g, static_cast<std::size_t>(sides.midpoint[g]), v);
      if (st.y() == 0.0 || st.y() == 1.0) unite(g, static_cast<std::size_t>(sides.seam[g]), v);
    }
  }
  MappedMap out;
  Mesh& mesh = out.mesh;
  std::vector<Index> vertex(tiles * nv, kNoIndex);
  std::set<Index> map_vertices, midpoints;
  for (std::size_t g = 0; g < tiles; ++g) {
    for (std::size_t v = 0; v < nv; ++v) {
      const Index root = find_root(parent, static_cast<Index>(g * nv + v));
      if (vertex[root] == kNoIndex)
        vertex[root] = mesh.add_vertex(grid_point(surface.mesh, surface.grids[g], shape.st[v]));
      vertex[g * nv + v] = vertex[root];
      if (shape.kind[v] == VertexKind::MapVertex) map_vertices.insert(vertex[root]);
      if (shape.kind[v] == VertexKind::EdgeMidpoint) midpoints.insert(vertex[root]);
    }
  }
  progress.step("faces", 0.5);
  const Orbits faces = face_orbits(source);
  std::vector<std::int32_t> face_label, tile_label;
  std::set<std::pair<Index, Index>> segments;
  for (std::size_t g = 0; g < tiles; ++g) {
    const bool flip = !surface.grids[g].counterclockwise;
    for (std::size_t k = 0; k < shape.triangles.size(); ++k) {
      const auto& t = shape.triangles[k];
      auto at = [&](int c) {
        return vertex[g * nv + static_cast<std::size_t>(t[static_cast<std::size_t>(c)])];
      };
      if (flip)
        mesh.add_face({at(0), at(2), at(1)});
      else
        mesh.add_face({at(0), at(1), at(2)});
      const Element flag = words.multiply(
          phi[g], pairing.flags[static_cast<std::size_t>(shape.triangle_flag[k])].element);
      face_label.push_back(faces.label[static_cast<std::size_t>(flag)]);
      tile_label.push_back(static_cast<std::int32_t>(g));
    }
    for (const auto& [u, v] : shape.map_edges) {
      const Index a = vertex[g * nv + static_cast<std::size_t>(u)];
      const Index b = vertex[g * nv + static_cast<std::size_t>(v)];
      segments.insert({std::min(a, b), std::max(a, b)});
    }
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
  stats.covers_once = covers_once(phi, words, pairing);
  const auto& labels = mesh.face_attributes.at(kFaceAttribute);
  stats.faces = std::set<std::int32_t>(labels.begin(), labels.end()).size();
  stats.faces_are_disks = faces_are_disks(mesh, faces.count);
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
