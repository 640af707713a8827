#include "quadmesh/integer_charts.h"

#include "base/error.h"
#include "param/poisson.h"

namespace tessera::quadmesh {
namespace {

// The unit square's corners, counterclockwise, as quad corners 0..3.
const Eigen::Vector2d kSquare[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

// The rotation r with J^r a == b for two integer vectors of one length, or -1.
int rotation_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  for (int r = 0; r < 4; ++r)
    if ((quarter_turns(a, r) - b).squaredNorm() < 1e-18) return r;
  return -1;
}

}  // namespace

std::vector<int> quad_valences(const Mesh& quads) {
  std::vector<int> valence(quads.vertex_count(), 0);
  for (Index v : quads.face_vertices) ++valence[v];
  return valence;
}

std::vector<Singularity> irregular_vertices(const Mesh& quads, const Connectivity& connectivity) {
  const std::vector<int> valence = quad_valences(quads);
  std::vector<Singularity> result;
  for (Index v = 0; v < quads.vertex_count(); ++v) {
    const int regular = connectivity.is_boundary_vertex(v) ? 2 : 4;
    if (valence[v] != regular) result.push_back({v, (regular - valence[v]) / 4.0, valence[v]});
  }
  return result;
}

IntegerCharts integer_charts(const Mesh& quads, const Connectivity& connectivity) {
  IntegerCharts result;
  result.triangles = triangulate(quads);
  if (result.triangles.face_count() != 2 * quads.face_count())
    throw Error("integer_charts() needs a pure quad mesh");
  result.connectivity = build_connectivity(result.triangles);
  const Connectivity& c = result.connectivity;
  SeamlessParam& param = result.param;
  // triangulate() fans quad (0, 1, 2, 3) into (0, 1, 2) and (0, 2, 3).
  param.uv.resize(result.triangles.corner_count());
  for (std::size_t q = 0; q < quads.face_count(); ++q) {
    const Index t = static_cast<Index>(6 * q);
    param.uv[t] = kSquare[0];
    param.uv[t + 1] = kSquare[1];
    param.uv[t + 2] = kSquare[2];
    param.uv[t + 3] = kSquare[0];
    param.uv[t + 4] = kSquare[2];
    param.uv[t + 5] = kSquare[3];
  }
  param.rotation.assign(c.halfedge_count(), 0);
  param.translation.assign(c.halfedge_count(), Eigen::Vector2d::Zero());
  param.cut.assign(c.edge_count(), 0);
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index t = c.twin[h];
    if (c.is_boundary_halfedge(t)) continue;
    // The edge a -> b in face(h) and in face(t), where t runs b -> a.
    const Eigen::Vector2d along_f = param.uv[c.next[h]] - param.uv[h];
    const Eigen::Vector2d along_g = param.uv[t] - param.uv[c.next[t]];
    const int r = rotation_between(along_f, along_g);
    if (r < 0) throw Error("integer_charts(): the charts of an edge do not match");
    param.rotation[h] = static_cast<std::uint8_t>(r);
    param.translation[h] = param.uv[c.next[t]] - quarter_turns(param.uv[h], r);
    if (r != 0 || param.translation[h].squaredNorm() > 0) param.cut[c.edge[h]] = 1;
  }
  // One parameter unit on the surface: the mean length of a quad edge (diagonals aside).
  double quad_edges = 0;
  std::size_t quad_edge_count = 0;
  for (std::size_t q = 0; q < quads.face_count(); ++q) {
    const std::span<const Index> f = quads.face(q);
    for (std::size_t k = 0; k < 4; ++k) {
      quad_edges += (quads.positions[f[(k + 1) % 4]] - quads.positions[f[k]]).norm();
      ++quad_edge_count;
    }
  }
  param.h = quad_edge_count ? quad_edges / double(quad_edge_count) : 1.0;
  param.singularities = irregular_vertices(quads, connectivity);
  return result;
}

}  // namespace tessera::quadmesh
