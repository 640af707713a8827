#include "remesh/remesh.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <string>

#include "remesh/smoothing.h"

namespace tessera::remesh {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The quad mesh under construction: its vertices with the surface normal under each.
struct QuadBuilder {
  Mesh mesh;
  std::vector<Eigen::Vector3d> normal;
  std::vector<bool> is_node;  // a node of the layout
  Index add(const SurfaceSample& s, bool node = false) {
    normal.push_back(s.normal);
    is_node.push_back(node);
    return mesh.add_vertex(s.position);
  }
};

// The quad-mesh vertex of every point on every side (nodes included, each once).
std::vector<std::vector<Index>> side_vertices(const layout::RefinedMesh& refined,
                                              const RemeshPrep& prep, const SideLengths& lengths,
                                              QuadBuilder& out) {
  std::map<Index, Index> node;  // refined vertex -> quad-mesh vertex
  std::vector<std::vector<Index>> result;
  for (std::size_t i = 0; i < prep.sides.sides.size(); ++i) {
    const LayoutSide& side = prep.sides.sides[i];
    const std::vector<SurfaceSample> points =
        side_points(refined, side, prep.tracks[i], lengths.segments[lengths.chain[i]]);
    std::vector<Index>& vertices = result.emplace_back();
    for (std::size_t k = 0; k < points.size(); ++k) {
      const bool end = k == 0 || k + 1 == points.size();
      if (!end) {
        vertices.push_back(out.add(points[k]));
        continue;
      }
      const Index at = k == 0 ? side.vertices.front() : side.vertices.back();
      const auto [it, added] = node.try_emplace(at, Index(out.mesh.vertex_count()));
      if (added) out.add(points[k], true);
      vertices.push_back(it->second);
    }
  }
  return result;
}

// Grid point (i, j) of a patch of n x m quads: on side 0 (j = 0, i from corner 0 to corner 1),
// side 1 (i = n), side 2 (j = m, from corner 2 to corner 3) or side 3 (i = 0), else inside.
struct PatchGrid {
  int n = 0, m = 0;
  std::array<const std::vector<Index>*, 4> side;
  std::array<bool, 4> forward;
  std::vector<Index> interior;

  Index on_side(int k, int position) const {
    const std::vector<Index>& v = *side[k];
    return forward[k] ? v[position] : v[v.size() - 1 - position];
  }
  Index at(int i, int j) const {
    if (j == 0) return on_side(0, i);
    if (i == n) return on_side(1, j);
    if (j == m) return on_side(2, n - i);
    if (i == 0) return on_side(3, m - j);
    return interior[std::size_t(i - 1) + std::size_t(j - 1) * (n - 1)];
  }
};

// The vertices on boundary edges (an edge of one quad only).
std::vector<Index> boundary_vertices(const Mesh& quads) {
  std::map<std::pair<Index, Index>, int> uses;
  for (std::size_t f = 0; f < quads.face_count(); ++f) {
    const auto v = quads.face(f);
    for (std::size_t k = 0; k < v.size(); ++k) ++uses[std::minmax(v[k], v[(k + 1) % v.size()])];
  }
  std::vector<Index> result;
  for (const auto& [edge, count] : uses)
    if (count == 1) result.insert(result.end(), {edge.first, edge.second});
  return result;
}

std::vector<std::vector<Index>> faces_by_patch(const Mesh& refined, std::size_t patch_count) {
  std::vector<std::vector<Index>> faces(patch_count);
  const std::vector<std::int32_t>& patch = refined.face_attributes.at("patch");
  for (Index f = 0; f < refined.face_count(); ++f) faces[patch[f]].push_back(f);
  return faces;
}

std::size_t extract_quads(const layout::QuadLayout& layout, const RemeshPrep& prep,
                          const SideLengths& lengths, QuadBuilder& out) {
  const layout::RefinedMesh& refined = layout.refined;
  const std::vector<std::vector<Index>> on_sides = side_vertices(refined, prep, lengths, out);
  std::vector<std::int32_t>& patch_of_quad = out.mesh.face_attributes["patch"];
  std::size_t unlocated = 0;
  for (std::size_t p = 0; p < prep.sides.patches.size(); ++p) {
    PatchGrid grid;
    grid.n = lengths.size[p][0];
    grid.m = lengths.size[p][1];
    for (int k = 0; k < 4; ++k) {
      grid.side[k] = &on_sides[prep.sides.patches[p][k].side];
      grid.forward[k] = prep.sides.patches[p][k].forward;
    }
    std::size_t missed = 0;
    for (const SurfaceSample& s :
         patch_interior_points(refined, prep.charts[p], grid.n, grid.m, missed))
      grid.interior.push_back(out.add(s));
    unlocated += missed;
    for (int j = 0; j < grid.m; ++j)
      for (int i = 0; i < grid.n; ++i) {
        out.mesh.add_face(
            {grid.at(i, j), grid.at(i + 1, j), grid.at(i + 1, j + 1), grid.at(i, j + 1)});
        patch_of_quad.push_back(static_cast<std::int32_t>(p));
      }
  }
  return unlocated;
}

void add_seconds(std::vector<layout::StageSeconds>& to, const std::string& stage, double seconds) {
  for (layout::StageSeconds& s : to)
    if (s.stage == stage) {
      s.seconds += seconds;
      return;
    }
  to.push_back({stage, seconds});
}

}  // namespace

RemeshPrep prepare_remesh(const layout::QuadLayout& layout) {
  RemeshPrep prep;
  auto start = Clock::now();
  const layout::RefinedMesh& refined = layout.refined;
  prep.connectivity = build_connectivity(refined.mesh);
  prep.sides =
      patch_sides(prep.connectivity, refined.mesh.face_attributes.at("patch"), layout.check);
  for (const LayoutSide& side : prep.sides.sides) {
    prep.tracks.push_back(side_track(refined, prep.connectivity, side));
    prep.length_3d.push_back(side_length_3d(refined, side));
  }
  prep.seconds.push_back({"integer lengths", seconds_since(start)});

  start = Clock::now();
  const std::vector<std::vector<Index>> faces =
      faces_by_patch(refined.mesh, layout.check.patch_count);
  for (std::size_t p = 0; p < prep.sides.patches.size(); ++p)
    prep.charts.push_back(
        patch_chart(refined, prep.connectivity, faces[p], layout.check.corners[p]));
  prep.seconds.push_back({"patch maps", seconds_since(start)});
  return prep;
}

QuadMesh remesh_prepared(const layout::QuadLayout& layout, const RemeshPrep& prep,
                         const SizeTarget& target, int smoothing_rounds, const Mesh* surface) {
  QuadMesh result;
  result.patch_count = layout.check.patch_count;
  auto start = Clock::now();
  std::vector<double> length;
  length.reserve(prep.tracks.size());
  for (const SideTrack& track : prep.tracks) length.push_back(track.length());
  result.lengths = integer_side_lengths(prep.sides, std::move(length), prep.length_3d, target);
  result.seconds.push_back({"integer lengths", seconds_since(start)});

  start = Clock::now();
  QuadBuilder out;
  result.unlocated_points = extract_quads(layout, prep, result.lengths, out);
  result.seconds.push_back({"patch maps", seconds_since(start)});

  if (smoothing_rounds > 0) {
    start = Clock::now();
    std::vector<bool> fixed = out.is_node;
    for (Index v : boundary_vertices(out.mesh)) fixed[v] = true;
    smooth_on_surface(out.mesh, out.normal, fixed, surface ? *surface : layout.refined.mesh,
                      smoothing_rounds);
    result.seconds.push_back({"smoothing", seconds_since(start)});
  }

  start = Clock::now();
  result.quality = quad_quality(out.mesh, out.normal);
  // The base complex of the quad mesh is the layout only if its irregular vertices are nodes.
  for (Index v : result.quality.irregular) result.irregular_off_nodes += !out.is_node[v];
  for (Index v : result.quality.nonpositive_corners)
    result.nonpositive_corners_at_nodes += out.is_node[v];
  result.mesh = std::move(out.mesh);
  result.seconds.push_back({"check", seconds_since(start)});
  return result;
}

QuadMesh remesh_layout(const layout::QuadLayout& layout, const SizeTarget& target,
                       int smoothing_rounds, const Mesh* surface) {
  const RemeshPrep prep = prepare_remesh(layout);
  QuadMesh result = remesh_prepared(layout, prep, target, smoothing_rounds, surface);
  for (const layout::StageSeconds& s : prep.seconds)
    add_seconds(result.seconds, s.stage, s.seconds);
  return result;
}

}  // namespace tessera::remesh
