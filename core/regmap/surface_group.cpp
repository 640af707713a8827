#include "regmap/surface_group.h"

#include <algorithm>
#include <set>

#include "base/error.h"

namespace tessera::regmap {

namespace {

std::string tile_name(std::size_t t) {
  return "quarter tube " + std::to_string(t);
}

// Per vertex: how many different tiles its faces belong to.
std::vector<std::size_t> tiles_at_vertices(const Mesh& mesh,
                                           const std::vector<std::int32_t>& tile) {
  std::vector<std::vector<std::int32_t>> seen(mesh.vertex_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    for (Index v : mesh.face(f)) {
      auto& list = seen[v];
      if (std::find(list.begin(), list.end(), tile[f]) == list.end()) list.push_back(tile[f]);
    }
  }
  std::vector<std::size_t> count;
  for (const auto& list : seen) count.push_back(list.size());
  return count;
}

struct TileParts {
  std::vector<Index> boundary_halfedge;  // per tile: one halfedge on its boundary
  std::vector<std::size_t> boundary_length, faces;
  std::vector<std::set<Index>> vertices;
  std::vector<std::set<Index>> edges;
};

TileParts tile_parts(const Mesh& mesh, const Connectivity& c, const std::vector<std::int32_t>& tile,
                     std::size_t tiles) {
  TileParts parts;
  parts.boundary_halfedge.assign(tiles, kNoIndex);
  parts.boundary_length.assign(tiles, 0);
  parts.faces.assign(tiles, 0);
  parts.vertices.resize(tiles);
  parts.edges.resize(tiles);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (tile[f] < 0 || static_cast<std::size_t>(tile[f]) >= tiles)
      throw TopologyError("face " + std::to_string(f) + " has tile " + std::to_string(tile[f]) +
                          ", outside 0.." + std::to_string(tiles - 1));
    const auto t = static_cast<std::size_t>(tile[f]);
    ++parts.faces[t];
    for (Index h = mesh.face_offsets[f]; h < mesh.face_offsets[f + 1]; ++h) {
      parts.vertices[t].insert(mesh.face_vertices[h]);
      parts.edges[t].insert(c.edge[h]);
      const Index across = c.face[c.twin[h]];
      if (across != kNoIndex && tile[across] == tile[f]) continue;
      ++parts.boundary_length[t];
      if (parts.boundary_halfedge[t] == kNoIndex) parts.boundary_halfedge[t] = h;
    }
  }
  return parts;
}

// The boundary of tile t, walked once around from `start`: its halfedges in order.
std::vector<Index> walk_boundary(const Connectivity& c, const std::vector<std::int32_t>& tile,
                                 Index start) {
  const std::int32_t t = tile[c.face[start]];
  std::vector<Index> loop;
  auto inside = [&](Index h) {
    const Index f = c.face[c.twin[h]];
    return f != kNoIndex && tile[f] == t;
  };
  Index h = start;
  do {
    loop.push_back(h);
    // Turn around the halfedge's end vertex, inside the tile, to the next boundary halfedge.
    Index next = c.next[h];
    for (std::size_t turns = 0; inside(next) && turns < c.halfedge_count(); ++turns)
      next = c.next[c.twin[next]];
    h = next;
  } while (h != start && loop.size() <= c.halfedge_count());
  return loop;
}

struct Side {
  std::int32_t neighbour;
  Index first;  // its first halfedge
};

// The sides of a boundary loop: maximal runs of halfedges with one tile across.
std::vector<Side> sides_of(const Connectivity& c, const std::vector<std::int32_t>& tile,
                           const std::vector<Index>& loop) {
  auto across = [&](Index h) {
    const Index f = c.face[c.twin[h]];
    return f == kNoIndex ? -1 : tile[f];
  };
  std::vector<Side> sides;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Index prev = loop[(i + loop.size() - 1) % loop.size()];
    if (across(loop[i]) != across(prev)) sides.push_back({across(loop[i]), loop[i]});
  }
  return sides;
}

}  // namespace

QuarterTubeAdjacency quarter_tube_adjacency(const Mesh& mesh, const Connectivity& c,
                                            const std::vector<std::int32_t>& tile,
                                            std::size_t tiles) {
  const TileParts parts = tile_parts(mesh, c, tile, tiles);
  const std::vector<std::size_t> tiles_at = tiles_at_vertices(mesh, tile);
  QuarterTubeAdjacency adj;
  for (Permutation* p : {&adj.a, &adj.b, &adj.c, &adj.d}) p->assign(tiles, -1);
  for (std::size_t t = 0; t < tiles; ++t) {
    if (parts.faces[t] == 0) throw TopologyError(tile_name(t) + " has no faces");
    const long euler = static_cast<long>(parts.vertices[t].size()) -
                       static_cast<long>(parts.edges[t].size()) + static_cast<long>(parts.faces[t]);
    if (parts.boundary_halfedge[t] == kNoIndex || euler != 1)
      throw TopologyError(tile_name(t) + " is not a disk (V - E + F = " + std::to_string(euler) +
                          ")");
    const std::vector<Index> loop = walk_boundary(c, tile, parts.boundary_halfedge[t]);
    if (loop.size() != parts.boundary_length[t])
      throw TopologyError(tile_name(t) + " has more than one boundary loop");
    std::vector<Side> sides = sides_of(c, tile, loop);
    // Four sides, b and d facing the same tile; a starts at a junction pole.
    if (sides.size() != 4 || sides[0].neighbour == sides[1].neighbour)
      throw TopologyError(tile_name(t) + " has " + std::to_string(sides.size()) +
                          " sides, not the four of a quarter tube");
    if (sides[0].neighbour == sides[2].neighbour)
      std::rotate(sides.begin(), sides.begin() + 1, sides.end());
    if (sides[1].neighbour != sides[3].neighbour || sides[0].neighbour == sides[2].neighbour)
      throw TopologyError(tile_name(t) + " does not meet one tile along both of its seams");
    if (tiles_at[c.from_vertex(sides[2].first)] > tiles_at[c.from_vertex(sides[0].first)])
      std::rotate(sides.begin(), sides.begin() + 2, sides.end());
    adj.a[t] = sides[0].neighbour;
    adj.b[t] = sides[1].neighbour;
    adj.c[t] = sides[2].neighbour;
    adj.d[t] = sides[3].neighbour;
  }
  return adj;
}

SurfaceGroup surface_group(const QuarterTubeAdjacency& adj) {
  SurfaceGroup group;
  const std::size_t n = adj.a.size();
  for (std::size_t t = 0; t < n; ++t) {
    group.a.push_back(adj.a[static_cast<std::size_t>(adj.c[t])]);
    group.b.push_back(adj.d[static_cast<std::size_t>(adj.a[t])]);
    group.c.push_back(adj.b[t]);
  }
  return group;
}

namespace {

enum class Move { A, Ai, B, Bi, C };

struct NamedWord {
  std::string name;
  std::vector<Move> moves;  // applied left to right
};

bool is_bijection(const Permutation& p) {
  std::vector<bool> hit(p.size(), false);
  for (std::int32_t x : p) {
    if (x < 0 || static_cast<std::size_t>(x) >= p.size() || hit[static_cast<std::size_t>(x)])
      return false;
    hit[static_cast<std::size_t>(x)] = true;
  }
  return true;
}

Permutation inverse_of(const Permutation& p) {
  Permutation inv(p.size(), -1);
  for (std::size_t i = 0; i < p.size(); ++i)
    inv[static_cast<std::size_t>(p[i])] = static_cast<std::int32_t>(i);
  return inv;
}

std::vector<Move> repeated(const std::vector<Move>& moves, int times) {
  std::vector<Move> out;
  for (int i = 0; i < times; ++i) out.insert(out.end(), moves.begin(), moves.end());
  return out;
}

// R -> A, S -> B, T -> CB (B first, then C).
std::vector<Move> substitute(const Word& w) {
  std::vector<Move> out;
  for (Letter x : w) {
    switch (x) {
      case Letter::R:
        out.push_back(Move::A);
        break;
      case Letter::Ri:
        out.push_back(Move::Ai);
        break;
      case Letter::S:
        out.push_back(Move::B);
        break;
      case Letter::Si:
        out.push_back(Move::Bi);
        break;
      case Letter::T:
        out.push_back(Move::B);
        out.push_back(Move::C);
        break;
    }
  }
  return out;
}

std::vector<NamedWord> surface_relators(const Presentation& presentation) {
  using enum Move;
  std::vector<NamedWord> words = {
      {"A^" + std::to_string(presentation.p), repeated({A}, presentation.p)},
      {"B^" + std::to_string(presentation.q), repeated({B}, presentation.q)},
      {"C^2", {C, C}},
      {"(CB)^2", {B, C, B, C}},
      {"(BA)^2", {A, B, A, B}},
      {"(CBA)^2", {A, B, C, A, B, C}}};
  for (const Word& w : presentation.relators)
    words.push_back({to_string(w) + " with R -> A, S -> B, T -> CB", substitute(w)});
  return words;
}

bool holds_everywhere(const std::vector<Move>& moves, const std::vector<const Permutation*>& perm) {
  const std::size_t n = perm[0]->size();
  for (std::size_t t = 0; t < n; ++t) {
    auto x = static_cast<std::int32_t>(t);
    for (Move m : moves) x = (*perm[static_cast<std::size_t>(m)])[static_cast<std::size_t>(x)];
    if (x != static_cast<std::int32_t>(t)) return false;
  }
  return true;
}

}  // namespace

RelationCheck check_relations(const SurfaceGroup& group, const Presentation& presentation) {
  RelationCheck check;
  for (const auto& [name, p] : {std::pair{"A", &group.a}, {"B", &group.b}, {"C", &group.c}}) {
    ++check.relators;
    if (!is_bijection(*p)) check.failures.push_back(std::string(name) + " is not a permutation");
  }
  if (!check.hold()) return check;
  const Permutation a_inv = inverse_of(group.a), b_inv = inverse_of(group.b);
  const std::vector<const Permutation*> perm = {&group.a, &a_inv, &group.b, &b_inv, &group.c};
  for (const NamedWord& w : surface_relators(presentation)) {
    ++check.relators;
    if (!holds_everywhere(w.moves, perm)) check.failures.push_back(w.name);
  }
  return check;
}

}  // namespace tessera::regmap
