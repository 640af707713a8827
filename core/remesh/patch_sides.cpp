#include "remesh/patch_sides.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "base/error.h"

namespace tessera::remesh {
namespace {

using EdgeKey = std::pair<Index, Index>;

EdgeKey undirected(Index a, Index b) {
  return {std::min(a, b), std::max(a, b)};
}

bool in_patch(const Connectivity& c, const std::vector<std::int32_t>& patch, Index h,
              std::int32_t p) {
  return !c.is_boundary_halfedge(h) && patch[c.face[h]] == p;
}

// The halfedge leaving v along the boundary of patch p, with p on its left (the boundary of a disk
// patch passes each of its vertices once).
Index boundary_halfedge_leaving(const Connectivity& c, const std::vector<std::int32_t>& patch,
                                Index v, std::int32_t p) {
  for (Index h : outgoing_halfedges(c, v))
    if (in_patch(c, patch, h, p) && !in_patch(c, patch, c.twin[h], p)) return h;
  return kNoIndex;
}

// The vertices of patch p's boundary from corner `from` to corner `to`.
std::vector<Index> walk_side(const Connectivity& c, const std::vector<std::int32_t>& patch,
                             std::int32_t p, Index from, Index to) {
  std::vector<Index> vertices{from};
  while (vertices.back() != to) {
    const Index h = boundary_halfedge_leaving(c, patch, vertices.back(), p);
    if (h == kNoIndex || vertices.size() > c.vertex_count())
      throw InputError("remesh: the boundary of patch " + std::to_string(p) +
                       " cannot be walked from corner vertex " + std::to_string(from) +
                       " to corner vertex " + std::to_string(to));
    vertices.push_back(c.to_vertex[h]);
  }
  return vertices;
}

// The same key for a side walked from either end: the smaller of its end edges.
std::pair<EdgeKey, EdgeKey> side_key(const std::vector<Index>& v) {
  const EdgeKey first = undirected(v[0], v[1]);
  const EdgeKey last = undirected(v[v.size() - 2], v.back());
  return {std::min(first, last), std::max(first, last)};
}

}  // namespace

PatchSides patch_sides(const Connectivity& connectivity, const std::vector<std::int32_t>& patch,
                       const layout::LayoutCheck& check) {
  if (!check.valid())
    throw InputError("remesh needs a valid layout; " +
                     (check.problems.empty() ? std::string("it has no patches")
                                             : "the layout check found: " + check.problems[0]));
  PatchSides result;
  result.patches.resize(check.patch_count);
  std::map<std::pair<EdgeKey, EdgeKey>, std::size_t> side_of;
  for (std::size_t p = 0; p < check.patch_count; ++p) {
    const std::vector<Index>& corners = check.corners[p];
    for (std::size_t k = 0; k < 4; ++k) {
      std::vector<Index> walked = walk_side(connectivity, patch, static_cast<std::int32_t>(p),
                                            corners[k], corners[(k + 1) % 4]);
      const auto [it, added] = side_of.try_emplace(side_key(walked), result.sides.size());
      if (added) result.sides.push_back({std::move(walked)});
      result.patches[p][k] = {it->second, result.sides[it->second].vertices.front() == corners[k]};
    }
  }
  return result;
}

}  // namespace tessera::remesh
