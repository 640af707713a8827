#include "regmap/platonic_base.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>

#include <Eigen/Geometry>

#include "regmap/map_isomorphism.h"

namespace tessera::regmap {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// ---- The solids -------------------------------------------------------------------------------

struct Solid {
  std::string name;
  std::vector<Vector3d> vertex;               // unit vectors
  std::vector<std::vector<int>> neighbour;    // counterclockwise seen from outside
  std::vector<std::array<int, 2>> edge;       // its two vertices
  std::map<std::array<int, 2>, int> edge_of;  // (v, w) in either order -> edge
  std::vector<std::vector<int>> face_edges;
  std::vector<Matrix3d> rotation;       // the solid's rotation group
  std::vector<std::vector<int>> moved;  // per rotation: where it takes each vertex

  int valence() const { return static_cast<int>(neighbour[0].size()); }
};

// A unit vector perpendicular to n.
Vector3d perpendicular(const Vector3d& n) {
  const Vector3d other = std::abs(n.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  return n.cross(other).normalized();
}

// The component of `towards` in the plane perpendicular to the unit vector n, normalized.
Vector3d tangential(const Vector3d& n, const Vector3d& towards) {
  return (towards - towards.dot(n) * n).normalized();
}

void find_neighbours(Solid& s) {
  double nearest = 4.0;
  for (std::size_t i = 0; i < s.vertex.size(); ++i)
    for (std::size_t j = i + 1; j < s.vertex.size(); ++j)
      nearest = std::min(nearest, (s.vertex[i] - s.vertex[j]).norm());
  s.neighbour.resize(s.vertex.size());
  for (std::size_t i = 0; i < s.vertex.size(); ++i) {
    const Vector3d& n = s.vertex[i];
    const Vector3d t1 = perpendicular(n), t2 = n.cross(t1);
    std::vector<std::pair<double, int>> around;
    for (std::size_t j = 0; j < s.vertex.size(); ++j) {
      if (i == j || (s.vertex[i] - s.vertex[j]).norm() > nearest * (1 + 1e-9)) continue;
      const Vector3d d = s.vertex[j] - n;
      around.push_back({std::atan2(d.dot(t2), d.dot(t1)), static_cast<int>(j)});
    }
    std::sort(around.begin(), around.end());
    for (const auto& [angle, j] : around) s.neighbour[i].push_back(j);
  }
  for (std::size_t i = 0; i < s.vertex.size(); ++i) {
    for (int j : s.neighbour[i]) {
      if (j < static_cast<int>(i)) continue;
      s.edge_of[{static_cast<int>(i), j}] = s.edge_of[{j, static_cast<int>(i)}] =
          static_cast<int>(s.edge.size());
      s.edge.push_back({static_cast<int>(i), j});
    }
  }
}

// Each face as its edges: walk from a directed edge v->w to w->(the neighbour of w before v, so
// that the face lies to the left).
void find_faces(Solid& s) {
  std::map<std::array<int, 2>, bool> used;
  for (std::size_t v = 0; v < s.vertex.size(); ++v) {
    for (int w0 : s.neighbour[v]) {
      if (used[{static_cast<int>(v), w0}]) continue;
      std::vector<int>& face = s.face_edges.emplace_back();
      int a = static_cast<int>(v), b = w0;
      while (!used[{a, b}]) {
        used[{a, b}] = true;
        face.push_back(s.edge_of.at({a, b}));
        const std::vector<int>& around = s.neighbour[static_cast<std::size_t>(b)];
        const auto at = std::find(around.begin(), around.end(), a) - around.begin();
        const int next = around[static_cast<std::size_t>(
            (at + static_cast<long>(around.size()) - 1) % static_cast<long>(around.size()))];
        a = b;
        b = next;
      }
    }
  }
}

// The rotations of the solid: one for every directed edge v0->v1 it can be taken to.
void find_rotations(Solid& s) {
  auto frame = [&](int v, int w) {
    const Vector3d a = s.vertex[static_cast<std::size_t>(v)];
    const Vector3d b = tangential(a, s.vertex[static_cast<std::size_t>(w)]);
    Matrix3d m;
    m << a, b, a.cross(b);
    return m;
  };
  const Matrix3d from = frame(0, s.neighbour[0][0]);
  for (std::size_t v = 0; v < s.vertex.size(); ++v) {
    for (int w : s.neighbour[v]) {
      const Matrix3d r = frame(static_cast<int>(v), w) * from.transpose();
      std::vector<int>& image = s.moved.emplace_back();
      for (const Vector3d& p : s.vertex) {
        const Vector3d q = r * p;
        for (std::size_t j = 0; j < s.vertex.size(); ++j)
          if ((s.vertex[j] - q).norm() < 1e-9) image.push_back(static_cast<int>(j));
      }
      s.rotation.push_back(r);
    }
  }
}

Solid make_solid(const std::string& name, std::vector<Vector3d> vertices) {
  Solid s;
  s.name = name;
  for (Vector3d& v : vertices) v.normalize();
  s.vertex = std::move(vertices);
  find_neighbours(s);
  find_faces(s);
  find_rotations(s);
  return s;
}

// The cyclic permutations of (a, b, c) with every sign.
void add_cyclic(std::vector<Vector3d>& out, double a, double b, double c) {
  for (int sa : {1, -1})
    for (int sb : {1, -1})
      for (int sc : {1, -1}) {
        if ((a == 0 && sa < 0) || (b == 0 && sb < 0) || (c == 0 && sc < 0)) continue;
        out.push_back({sa * a, sb * b, sc * c});
        out.push_back({sb * b, sc * c, sa * a});
        out.push_back({sc * c, sa * a, sb * b});
      }
}

std::vector<Solid> platonic_solids() {
  const double phi = std::numbers::phi;
  std::vector<Vector3d> tetrahedron = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  std::vector<Vector3d> cube;
  for (int x : {1, -1})
    for (int y : {1, -1})
      for (int z : {1, -1}) cube.push_back({double(x), double(y), double(z)});
  std::vector<Vector3d> octahedron;
  add_cyclic(octahedron, 1, 0, 0);
  std::vector<Vector3d> icosahedron;
  add_cyclic(icosahedron, 0, 1, phi);
  std::vector<Vector3d> dodecahedron = cube;
  add_cyclic(dodecahedron, 0, 1 / phi, phi);
  return {make_solid("Tetrahedron", tetrahedron), make_solid("Cube", cube),
          make_solid("Octahedron", octahedron), make_solid("Dodecahedron", dodecahedron),
          make_solid("Icosahedron", icosahedron)};
}

// ---- The branching cochain --------------------------------------------------------------------

using Cochain = std::vector<std::uint8_t>;

bool branches_at_every_face(const Solid& s, const Cochain& c) {
  for (const std::vector<int>& face : s.face_edges) {
    int sum = 0;
    for (int e : face) sum += c[static_cast<std::size_t>(e)];
    if (sum % 2 == 0) return false;
  }
  return true;
}

// The rotations (indices) that keep c.
std::vector<std::size_t> keeping(const Solid& s, const Cochain& c) {
  std::vector<std::size_t> kept;
  for (std::size_t r = 0; r < s.rotation.size(); ++r) {
    bool keeps = true;
    for (std::size_t e = 0; e < s.edge.size() && keeps; ++e) {
      const auto [v, w] = s.edge[e];
      const int image = s.edge_of.at(
          {s.moved[r][static_cast<std::size_t>(v)], s.moved[r][static_cast<std::size_t>(w)]});
      keeps = c[static_cast<std::size_t>(image)] == c[e];
    }
    if (keeps) kept.push_back(r);
  }
  return kept;
}

// c = 1 everywhere when that branches at every face, else (the cube, 12 edges) the branching c
// kept by the most rotations, the first in counting order among equals.
Cochain branching_cochain(const Solid& s) {
  Cochain ones(s.edge.size(), 1);
  if (branches_at_every_face(s, ones)) return ones;
  Cochain best;
  std::size_t most = 0;
  for (std::uint32_t bits = 0; bits < (1u << s.edge.size()); ++bits) {
    Cochain c(s.edge.size());
    for (std::size_t e = 0; e < c.size(); ++e) c[e] = static_cast<std::uint8_t>((bits >> e) & 1u);
    if (!branches_at_every_face(s, c)) continue;
    const std::size_t kept = keeping(s, c).size();
    if (kept > most) {
      most = kept;
      best = c;
    }
  }
  return best;
}

// ---- The double cover -------------------------------------------------------------------------

// Lifted node (v, sheet) is sheet * V + v; lifted dart (node, slot k) is node * q + k, leaving
// along the solid's k-th neighbour of v.
struct DoubleCover {
  RotationSystem rotation;
  std::size_t vertices = 0;
  int valence = 0;
};

DoubleCover double_cover(const Solid& s, const Cochain& c) {
  DoubleCover cover;
  cover.vertices = s.vertex.size();
  cover.valence = s.valence();
  const int q = cover.valence;
  for (int sheet = 0; sheet < 2; ++sheet) {
    for (std::size_t v = 0; v < s.vertex.size(); ++v) {
      const int node = sheet * static_cast<int>(cover.vertices) + static_cast<int>(v);
      for (int k = 0; k < q; ++k) {
        cover.rotation.next_around.push_back(node * q + (k + 1) % q);
        const int w = s.neighbour[v][static_cast<std::size_t>(k)];
        const int to_sheet =
            (sheet + c[static_cast<std::size_t>(s.edge_of.at({static_cast<int>(v), w}))]) % 2;
        const std::vector<int>& back = s.neighbour[static_cast<std::size_t>(w)];
        const auto at = std::find(back.begin(), back.end(), static_cast<int>(v)) - back.begin();
        cover.rotation.opposite.push_back((to_sheet * static_cast<int>(cover.vertices) + w) * q +
                                          static_cast<int>(at));
      }
    }
  }
  return cover;
}

// ---- Placement --------------------------------------------------------------------------------

struct Radii {
  double inner = 0.0, outer = 0.0, apart = 0.0;
};

// The inner sheet's edges get tubes of about unit length; the outer sheet is a third larger; the
// midpoints of a crossing pair are four clearances apart.
Radii radii_for(const Solid& s, const TubeShape& shape) {
  const double half_angle =
      std::acos(std::clamp(s.vertex[0].dot(s.vertex[static_cast<std::size_t>(s.neighbour[0][0])]),
                           -1.0, 1.0)) /
      2;
  Radii r;
  r.inner = (shape.reach + shape.arm + 0.8) / std::sin(half_angle);
  r.outer = 1.35 * r.inner;
  r.apart = 2.0 * shape.clearance;
  return r;
}

// The waypoint of an edge between lifted nodes (v, s) and (w, t).
Vector3d edge_midpoint(const Vector3d& v, int s, const Vector3d& w, int t, const Radii& r) {
  const Vector3d middle = (v + w).normalized();
  if (s == t) return (s == 0 ? r.inner : r.outer) * middle;
  const Vector3d& inner = s == 0 ? v : w;
  const Vector3d& outer = s == 0 ? w : v;
  return 0.5 * (r.inner + r.outer) * middle + r.apart * inner.cross(outer).normalized();
}

SymmetricPlacement place(const Solid& s, const Cochain& c, const DoubleCover& cover,
                         const std::vector<std::int32_t>& phi, const EdgeGraph& graph,
                         const JunctionOrder& order, const TubeShape& shape) {
  const int q = cover.valence;
  const Radii radii = radii_for(s, shape);
  auto lifted = [&](std::int32_t dart) {  // (vertex, sheet, slot) of the image of a graph dart
    const int image = phi[static_cast<std::size_t>(dart)];
    const int node = image / q;
    return std::array<int, 3>{node % static_cast<int>(cover.vertices),
                              node / static_cast<int>(cover.vertices), image % q};
  };
  SymmetricPlacement placement;
  placement.name = "2-" + s.name;
  EmbeddedGraph& embedded = placement.embedded;
  embedded.reach = shape.reach;
  embedded.arm = shape.arm;
  for (std::size_t u = 0; u < graph.node_count; ++u) {
    const auto [v, sheet, k] = lifted(order.node_darts[u][0]);
    const Vector3d& n = s.vertex[static_cast<std::size_t>(v)];
    const Vector3d e1 =
        tangential(n, s.vertex[static_cast<std::size_t>(
                          s.neighbour[static_cast<std::size_t>(v)][static_cast<std::size_t>(k)])]);
    Matrix3d frame;
    frame << e1, n.cross(e1), n;
    embedded.node_frame.push_back(frame);
    embedded.node_position.push_back((sheet == 0 ? radii.inner : radii.outer) * n);
  }
  for (std::size_t e = 0; e < graph.edge_count; ++e) {
    const auto [va, sa, ka] = lifted(order.edge_darts[e][0]);
    const auto [vb, sb, kb] = lifted(order.edge_darts[e][1]);
    embedded.edge_path.push_back(
        {edge_midpoint(s.vertex[static_cast<std::size_t>(va)], sa,
                       s.vertex[static_cast<std::size_t>(vb)], sb, radii)});
  }
  for (std::size_t r : keeping(s, c)) placement.symmetries.push_back(s.rotation[r]);
  return placement;
}

}  // namespace

std::optional<SymmetricPlacement> platonic_placement(const EdgeGraph& graph,
                                                     const JunctionOrder& order,
                                                     const TubeShape& shape) {
  const RotationSystem target{graph.next_around, graph.opposite};
  for (const Solid& s : platonic_solids()) {
    if (graph.node_count != 2 * s.vertex.size() || order.valence != s.valence()) continue;
    const Cochain c = branching_cochain(s);
    const DoubleCover cover = double_cover(s, c);
    if (const auto phi = find_map_isomorphism(target, cover.rotation))
      return place(s, c, cover, *phi, graph, order, shape);
  }
  return std::nullopt;
}

}  // namespace tessera::regmap
