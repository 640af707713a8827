#include "layout/refine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "base/error.h"

namespace tessera::layout {
namespace {

using Barycentric = Eigen::Vector3d;

// Edge parameters closer than this are one point (two arcs crossing on the edge).
constexpr double kSamePoint = 1e-12;

std::pair<Index, Index> sorted_pair(Index a, Index b) {
  return {std::min(a, b), std::max(a, b)};
}

// Lists of items grouped by a key in [0, keys), flat: the items of key k are
// items[offsets[k]] .. items[offsets[k + 1] - 1], in their order in the sorted input.
template <typename Item>
struct Grouped {
  std::vector<Index> offsets;
  std::vector<Item> items;

  std::span<const Item> of(Index key) const {
    return {items.data() + offsets[key], items.data() + offsets[key + 1]};
  }
};

// Groups sorted (key, item) pairs; `keep(previous, item)` says whether an item following
// `previous` in its group is kept (to merge near-duplicates).
template <typename Item, typename Keep>
Grouped<Item> group_sorted(const std::vector<std::pair<Index, Item>>& keyed, std::size_t keys,
                           Keep keep) {
  Grouped<Item> grouped;
  grouped.offsets.assign(keys + 1, 0);
  grouped.items.reserve(keyed.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    const auto& [key, item] = keyed[k];
    if (k > 0 && keyed[k - 1].first == key && !keep(grouped.items.back(), item)) continue;
    grouped.items.push_back(item);
    ++grouped.offsets[key + 1];
  }
  for (std::size_t key = 0; key < keys; ++key) grouped.offsets[key + 1] += grouped.offsets[key];
  return grouped;
}

// The points the arcs put on input edges, numbered as refined vertices after the input's: per
// edge, (parameter, vertex) by increasing parameter.
class EdgePoints {
 public:
  EdgePoints(const Connectivity& c, const std::vector<Arc>& arcs, Index first) {
    std::vector<std::pair<Index, std::pair<double, Index>>> keyed;
    for (const Arc& arc : arcs)
      for (const ArcPiece& piece : arc.pieces)
        for (const SurfacePoint& p : {piece.from, piece.to})
          if (p.edge != kNoIndex) keyed.push_back({p.edge, {p.t, kNoIndex}});
    std::sort(keyed.begin(), keyed.end());
    points_ = group_sorted(keyed, c.edge_count(), [](const auto& previous, const auto& point) {
      return point.first - previous.first > kSamePoint;
    });
    for (auto& point : points_.items) point.second = first++;
  }
  Index vertex_of(const SurfacePoint& p) const {
    if (p.vertex != kNoIndex) return p.vertex;
    const auto list = on(p.edge);
    auto it = std::lower_bound(list.begin(), list.end(), std::pair{p.t - kSamePoint, Index(0)});
    if (it == list.end()) --it;
    return it->second;
  }
  std::span<const std::pair<double, Index>> on(Index edge) const { return points_.of(edge); }

 private:
  Grouped<std::pair<double, Index>> points_;
};

// The arcs' pieces sorted by face: chords between two refined vertices, and the pieces that run
// along an input edge (both ends input vertices) as refined-vertex chains.
struct PiecesByFace {
  Grouped<std::pair<Index, Index>> chords;
  std::vector<std::pair<Index, Index>> along_edges;  // input vertex pairs
};

PiecesByFace sort_pieces(const Mesh& mesh, const std::vector<Arc>& arcs, const EdgePoints& points) {
  PiecesByFace result;
  std::vector<std::pair<Index, std::pair<Index, Index>>> keyed;
  for (const Arc& arc : arcs) {
    for (const ArcPiece& piece : arc.pieces) {
      const Index a = points.vertex_of(piece.from), b = points.vertex_of(piece.to);
      if (a == b) continue;
      if (piece.from.vertex != kNoIndex && piece.to.vertex != kNoIndex)
        result.along_edges.push_back(sorted_pair(a, b));
      else
        keyed.push_back({piece.face, sorted_pair(a, b)});
    }
  }
  std::sort(keyed.begin(), keyed.end());
  result.chords =
      group_sorted(keyed, mesh.face_count(),
                   [](const auto& previous, const auto& chord) { return chord != previous; });
  return result;
}

// The arrangement of one face: nodes on its boundary cycle and at chord crossings, the edges
// between them, its faces, their triangles. One object serves every face in turn (reset()), so
// that its lists keep their memory.
class FaceArrangement {
 public:
  FaceArrangement(const Charts& charts, RefinedMesh& out) : charts_(charts), out_(out) {}

  void reset(const EdgePoints& points, Index face) {
    face_ = face;
    cycle_.clear();
    bary_.clear();
    vertex_.clear();
    place_corners();
    build_cycle(points);
  }

  void cut(std::span<const std::pair<Index, Index>> chords) {
    std::vector<std::array<Index, 2>> local;
    for (const auto& [a, b] : chords) local.push_back({local_node(a), local_node(b)});
    std::vector<std::vector<std::pair<double, Index>>> along(local.size());
    for (std::size_t i = 0; i < local.size(); ++i) {
      for (std::size_t j = i + 1; j < local.size(); ++j) {
        if (!interleave(local[i], local[j])) continue;
        const auto [si, sj] = intersection(local[i], local[j]);
        const Index node = add_node((1 - si) * bary_[local[i][0]] + si * bary_[local[i][1]]);
        along[i].push_back({si, node});
        along[j].push_back({sj, node});
      }
    }
    for (std::size_t i = 0; i < local.size(); ++i) {
      std::sort(along[i].begin(), along[i].end());
      Index previous = local[i][0];
      along[i].push_back({1.0, local[i][1]});
      for (const auto& [s, node] : along[i]) {
        connect(previous, node);
        out_.arc_edges.push_back(sorted_pair(vertex_[previous], vertex_[node]));
        previous = node;
      }
    }
  }

  void triangulate() {
    for (std::size_t k = 0; k < cycle_.size(); ++k)
      connect(cycle_[k], cycle_[(k + 1) % cycle_.size()]);
    sort_neighbours();
    const Index nodes = node_count();
    slot_start_.assign(nodes + 1, 0);
    for (Index v = 0; v < nodes; ++v) slot_start_[v + 1] = slot_start_[v] + adjacent_[v].size();
    used_.assign(slot_start_[nodes], 0);
    // The outside lies left of the boundary cycle walked backwards; every other walk is a piece
    // of the triangle, however thin (a sign test on the area would drop slivers and leave holes).
    walk_face(cycle_[1], slot_of(cycle_[1], cycle_[0]));
    for (Index v = 0; v < nodes; ++v) {
      for (std::size_t k = 0; k < adjacent_[v].size(); ++k) {
        if (used_[slot_start_[v] + k]) continue;
        walk_face(v, k);
        emit_polygon(polygon_);
      }
    }
  }

 private:
  void place_corners() {
    const Index c = charts_.first_corner(face_);
    for (int k = 0; k < 3; ++k) corner_position_[k] = charts_.mesh.positions[charts_.vertex(c + k)];
    const Eigen::Vector3d e1 = corner_position_[1] - corner_position_[0];
    const Eigen::Vector3d e2 = corner_position_[2] - corner_position_[0];
    const Eigen::Vector3d x = e1.normalized();
    const double along = e2.dot(x);
    plane_[0] = {0, 0};
    plane_[1] = {e1.norm(), 0};
    plane_[2] = {along, (e2 - along * x).norm()};
  }

  void build_cycle(const EdgePoints& points) {
    const Connectivity& c = charts_.connectivity;
    const Index first = charts_.first_corner(face_);
    for (int k = 0; k < 3; ++k) {
      const Index h = first + k;
      corner_node_[k] = add_node(Barycentric::Unit(k), charts_.vertex(h));
      cycle_.push_back(corner_node_[k]);
      const Index edge = c.edge[h];
      const bool forward = c.edge_halfedge[edge] == h;
      std::vector<std::pair<double, Index>> on_edge;
      for (const auto& [t, vertex] : points.on(edge))
        on_edge.push_back({forward ? t : 1 - t, vertex});
      std::sort(on_edge.begin(), on_edge.end());
      for (const auto& [s, vertex] : on_edge)
        cycle_.push_back(
            add_node((1 - s) * Barycentric::Unit(k) + s * Barycentric::Unit((k + 1) % 3), vertex));
    }
  }

  Index add_node(const Barycentric& b, Index vertex = kNoIndex) {
    if (vertex == kNoIndex) {
      vertex = static_cast<Index>(out_.mesh.positions.size());
      out_.mesh.positions.push_back(b[0] * corner_position_[0] + b[1] * corner_position_[1] +
                                    b[2] * corner_position_[2]);
    }
    bary_.push_back(b);
    vertex_.push_back(vertex);
    const Index node = static_cast<Index>(bary_.size() - 1);
    if (node < adjacent_.size()) {
      adjacent_[node].clear();
    } else {
      adjacent_.emplace_back();
    }
    return node;
  }

  Index node_count() const { return static_cast<Index>(bary_.size()); }

  Eigen::Vector2d planar(Index node) const {
    return bary_[node][0] * plane_[0] + bary_[node][1] * plane_[1] + bary_[node][2] * plane_[2];
  }

  Index local_node(Index vertex) const {
    for (Index k = 0; k < cycle_.size(); ++k)
      if (vertex_[cycle_[k]] == vertex) return cycle_[k];
    throw Error("an arc piece ends off its face's boundary");
  }

  // Chords cross iff exactly one end of one lies strictly between the ends of the other along the
  // boundary cycle (cycle nodes are numbered in cycle order).
  static bool interleave(const std::array<Index, 2>& p, const std::array<Index, 2>& q) {
    if (p[0] == q[0] || p[0] == q[1] || p[1] == q[0] || p[1] == q[1]) return false;
    const Index low = std::min(p[0], p[1]), high = std::max(p[0], p[1]);
    const bool first_inside = q[0] > low && q[0] < high;
    const bool second_inside = q[1] > low && q[1] < high;
    return first_inside != second_inside;
  }

  // Parameters of the crossing along each chord.
  std::pair<double, double> intersection(const std::array<Index, 2>& p,
                                         const std::array<Index, 2>& q) const {
    const Eigen::Vector2d a = planar(p[0]), da = planar(p[1]) - a;
    const Eigen::Vector2d b = planar(q[0]), db = planar(q[1]) - b;
    const double d = cross(da, db);
    const double s = d == 0 ? 0.5 : cross(b - a, db) / d;
    const double t = d == 0 ? 0.5 : cross(b - a, da) / d;
    return {std::clamp(s, 0.0, 1.0), std::clamp(t, 0.0, 1.0)};
  }

  void connect(Index a, Index b) {
    if (std::find(adjacent_[a].begin(), adjacent_[a].end(), b) != adjacent_[a].end()) return;
    adjacent_[a].push_back(b);
    adjacent_[b].push_back(a);
  }

  // Each node's neighbours by increasing angle of the direction to them, in (-pi, pi] (the order
  // of atan2), compared exactly: first the lower half-plane, then by the sign of the cross product
  // (on the upper half-plane's rim, direction 0 before direction pi), ties by node number.
  void sort_neighbours() {
    const auto before = [](const Direction& a, const Direction& b) {
      const bool a_upper = a.d.y() >= 0, b_upper = b.d.y() >= 0;
      if (a_upper != b_upper) return b_upper;
      const double turn = cross(a.d, b.d);
      if (turn != 0) return turn > 0;
      if ((a.d.x() > 0) != (b.d.x() > 0) && a.d.dot(b.d) < 0) return a.d.x() > 0;
      return a.node < b.node;
    };
    for (Index v = 0; v < node_count(); ++v) {
      const Eigen::Vector2d p = planar(v);
      by_angle_.clear();
      for (Index a : adjacent_[v]) {
        const Eigen::Vector2d d = planar(a) - p;
        by_angle_.push_back({d.isZero(0) ? Eigen::Vector2d(1, 0) : d, a});  // atan2(0, 0) = 0
      }
      std::sort(by_angle_.begin(), by_angle_.end(), before);
      for (std::size_t k = 0; k < by_angle_.size(); ++k) adjacent_[v][k] = by_angle_[k].node;
    }
  }

  std::size_t slot_of(Index from, Index to) const {
    const auto& around = adjacent_[from];
    return std::find(around.begin(), around.end(), to) - around.begin();
  }

  // The face on the left of the directed edge v -> adjacent_[v][k], into polygon_: at each node
  // turn to the neighbour next clockwise from the one we came from.
  void walk_face(Index v, std::size_t k) {
    polygon_.clear();
    Index from = v;
    std::size_t slot = k;
    while (!used_[slot_start_[from] + slot]) {
      used_[slot_start_[from] + slot] = 1;
      polygon_.push_back(from);
      const Index to = adjacent_[from][slot];
      const std::size_t around = adjacent_[to].size();
      slot = (slot_of(to, from) + around - 1) % around;
      from = to;
    }
  }

  double triangle_area(Index a, Index b, Index c) const {
    return cross(planar(b) - planar(a), planar(c) - planar(a)) / 2;
  }

  // A convex polygon: fanned from the first corner whose fan has no flat triangle, or else from an
  // added centre point.
  void emit_polygon(const std::vector<Index>& polygon) {
    const std::size_t n = polygon.size();
    const double flat = 1e-12 * triangle_area(corner_node_[0], corner_node_[1], corner_node_[2]);
    for (std::size_t apex = 0; apex < n; ++apex) {
      bool good = true;
      for (std::size_t i = 1; i + 1 < n && good; ++i)
        good = triangle_area(polygon[apex], polygon[(apex + i) % n], polygon[(apex + i + 1) % n]) >
               flat;
      if (!good) continue;
      for (std::size_t i = 1; i + 1 < n; ++i)
        emit_triangle(polygon[apex], polygon[(apex + i) % n], polygon[(apex + i + 1) % n]);
      return;
    }
    Barycentric centre = Barycentric::Zero();
    for (Index node : polygon) centre += bary_[node] / double(n);
    const Index middle = add_node(centre);
    for (std::size_t i = 0; i < n; ++i) emit_triangle(middle, polygon[i], polygon[(i + 1) % n]);
  }

  void emit_triangle(Index a, Index b, Index c) {
    out_.mesh.add_face({vertex_[a], vertex_[b], vertex_[c]});
    out_.parent.push_back(face_);
    const Index first = charts_.first_corner(face_);
    for (Index node : {a, b, c}) {
      const Barycentric& w = bary_[node];
      out_.uv.push_back(w[0] * charts_.uv(first) + w[1] * charts_.uv(first + 1) +
                        w[2] * charts_.uv(first + 2));
    }
  }

  const Charts& charts_;
  Index face_ = kNoIndex;
  RefinedMesh& out_;
  std::array<Eigen::Vector3d, 3> corner_position_;
  std::array<Eigen::Vector2d, 3> plane_;
  std::array<Index, 3> corner_node_{};
  std::vector<Index> cycle_;
  std::vector<Barycentric> bary_;
  std::vector<Index> vertex_;
  std::vector<std::vector<Index>> adjacent_;  // the first node_count() lists are this face's
  struct Direction {
    Eigen::Vector2d d;  // from the node to its neighbour, in the face's plane
    Index node;
  };
  std::vector<Direction> by_angle_;
  std::vector<std::size_t> slot_start_;  // per node, its first entry in used_
  std::vector<std::uint8_t> used_;       // per node and neighbour: walked
  std::vector<Index> polygon_;
};

void copy_face(const Charts& charts, Index face, RefinedMesh& out) {
  const Index first = charts.first_corner(face);
  out.mesh.add_face({charts.vertex(first), charts.vertex(first + 1), charts.vertex(first + 2)});
  out.parent.push_back(face);
  for (Index h = first; h < first + 3; ++h) out.uv.push_back(charts.uv(h));
}

// Runs along input edges: every stretch between consecutive refined vertices is on the arc.
void add_along_edges(const Charts& charts, const std::vector<std::pair<Index, Index>>& along,
                     const EdgePoints& points, RefinedMesh& out) {
  const Connectivity& c = charts.connectivity;
  for (const auto& [a, b] : along) {
    for (Index h : outgoing_halfedges(c, a)) {
      if (c.to_vertex[h] != b) continue;
      const Index edge = c.edge[h];
      const Index origin = c.from_vertex(c.edge_halfedge[edge]);
      Index previous = origin;
      for (const auto& [t, vertex] : points.on(edge)) {
        out.arc_edges.push_back(sorted_pair(previous, vertex));
        previous = vertex;
      }
      out.arc_edges.push_back(sorted_pair(previous, origin == a ? b : a));
      break;
    }
  }
}

}  // namespace

RefinedMesh refine_along_arcs(const Charts& charts, const std::vector<Arc>& arcs) {
  const Mesh& mesh = charts.mesh;
  const Connectivity& c = charts.connectivity;
  RefinedMesh out;
  out.mesh.positions = mesh.positions;
  const EdgePoints points(c, arcs, static_cast<Index>(mesh.vertex_count()));
  for (Index e = 0; e < c.edge_count(); ++e)
    for (const auto& point : points.on(e))
      out.mesh.positions.push_back(position_of(mesh, c, {kNoIndex, e, point.first}));
  const PiecesByFace pieces = sort_pieces(mesh, arcs, points);
  FaceArrangement arrangement(charts, out);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index first = charts.first_corner(f);
    bool touched = !pieces.chords.of(f).empty();
    for (Index h = first; h < first + 3 && !touched; ++h) touched = !points.on(c.edge[h]).empty();
    if (!touched) {
      copy_face(charts, f, out);
      continue;
    }
    arrangement.reset(points, f);
    arrangement.cut(pieces.chords.of(f));
    arrangement.triangulate();
  }
  add_along_edges(charts, pieces.along_edges, points, out);
  std::sort(out.arc_edges.begin(), out.arc_edges.end());
  out.arc_edges.erase(std::unique(out.arc_edges.begin(), out.arc_edges.end()), out.arc_edges.end());
  return out;
}

}  // namespace tessera::layout
