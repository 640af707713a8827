#include "field/field_topology.h"

#include <cmath>
#include <numbers>

#include "mesh/boundary_tangents.h"
#include "mesh/geometry.h"

namespace tessera {
namespace {

constexpr double kQuarter = std::numbers::pi / 2;

// The angle reduced modulo a quarter turn to [-pi/4, pi/4].
double reduce_quarter(double a) {
  return std::remainder(a, kQuarter);
}

// The turn that aligns the field of the face of corner halfedge h with h's direction, read
// through the boundary curve's tangent there (mesh/boundary_tangents.h): the field's quarter
// turn closest to the tangent (in [-pi/4, pi/4]), plus the tangent's angle to the edge. Boundary
// edges use it where interior edges use the turn delta: the boundary index reads the field
// relative to the boundary (cross_field.h). On a staircase boundary the edges stand up to 60
// degrees off the field, which reduced on its own would put a quarter of index on the wrong vertex.
double boundary_alignment(const Mesh& mesh, const Connectivity& c, const FaceFrames& frames,
                          const BoundaryTangents& boundary, const std::vector<double>& angle,
                          Index h) {
  const Index f = c.face[h];
  const Eigen::Vector3d edge = halfedge_vector(mesh, c, h);
  // The boundary curve's tangent runs along the boundary halfedge, h's twin: reversed, along h.
  const Eigen::Vector3d tangent = -boundary.edge_tangent[c.edge[h]];
  const double edge_angle = frames.angle(f, edge);
  const double tangent_angle = frames.angle(f, tangent);
  return reduce_quarter(angle[f] - tangent_angle) +
         std::remainder(tangent_angle - edge_angle, 2 * std::numbers::pi);
}

}  // namespace

Matching principal_matching(const Connectivity& c, const std::vector<double>& angle,
                            const std::vector<double>& kappa) {
  Matching m;
  m.period_jump.assign(c.halfedge_count(), 0);
  m.turn.assign(c.halfedge_count(), 0.0);
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (c.is_boundary_edge(e)) continue;
    const Index h = c.edge_halfedge[e];
    const Index t = c.twin[h];
    // theta_j = theta_i + kappa_ij - p_ij * pi/2 + delta_ij (cross_field.h).
    const double mismatch = angle[c.face[h]] + kappa[h] - angle[c.face[t]];
    const long p = std::lround(mismatch / kQuarter);
    const int jump = static_cast<int>(((p % 4) + 4) % 4);
    m.period_jump[h] = static_cast<std::uint8_t>(jump);
    m.period_jump[t] = static_cast<std::uint8_t>((4 - jump) % 4);
    m.turn[h] = p * kQuarter - mismatch;
    m.turn[t] = -m.turn[h];
  }
  return m;
}

std::vector<int> vertex_indices(const Mesh& mesh, const Connectivity& c, const FaceFrames& frames,
                                const std::vector<double>& angle, const std::vector<double>& turn) {
  std::vector<int> index(c.vertex_count(), 0);
  const BoundaryTangents boundary = boundary_tangents(mesh, c);
  for (Index v = 0; v < c.vertex_count(); ++v) {
    const std::vector<Index> out = outgoing_halfedges(c, v);
    if (out.empty()) continue;
    // Counterclockwise, the face of outgoing halfedge h is followed by the face of
    // twin(prev(h)), across halfedge prev(h).
    double curvature = c.is_boundary_vertex(v) ? std::numbers::pi : 2 * std::numbers::pi;
    double turning = 0;
    for (Index h : out) {
      if (c.is_boundary_halfedge(h)) continue;
      curvature -= corner_angle(mesh, c, h);
      const Index across = c.prev[h];
      if (c.is_boundary_halfedge(c.twin[h]))
        turning += boundary_alignment(mesh, c, frames, boundary, angle, h);
      if (c.is_boundary_halfedge(c.twin[across]))
        turning -= boundary_alignment(mesh, c, frames, boundary, angle, across);
      else
        turning += turn[across];
    }
    index[v] = static_cast<int>(std::lround(4 * (curvature + turning) / (2 * std::numbers::pi)));
  }
  return index;
}

namespace {

// The halfedge x -> v of the interior neighbour x of v that split_merged_singularities() moves a
// quarter of v's index to, or kNoIndex.
Index quarter_target(const Connectivity& c, const Matching& matching,
                     const std::vector<int>& vertex_index, Index v) {
  Index best = kNoIndex;
  for (Index h : outgoing_halfedges(c, v)) {
    const Index into_v = c.twin[h];
    const Index x = c.to_vertex[h];
    if (c.is_boundary_vertex(x) || vertex_index[x] > 0) continue;
    if (best == kNoIndex || matching.turn[into_v] > matching.turn[best]) best = into_v;
  }
  return best;
}

}  // namespace

void split_merged_singularities(const Connectivity& c, Matching& matching,
                                std::vector<int>& vertex_index) {
  for (Index v = 0; v < c.vertex_count(); ++v) {
    if (c.is_boundary_vertex(v)) continue;
    while (vertex_index[v] >= 2) {
      // v's index counts the turn of every halfedge into v (vertex_indices()), its neighbour's
      // the twin's: a quarter less turn into v moves a quarter of index from v to the neighbour.
      const Index into_v = quarter_target(c, matching, vertex_index, v);
      if (into_v == kNoIndex) break;
      const Index out_of_v = c.twin[into_v];
      matching.turn[into_v] -= kQuarter;
      matching.turn[out_of_v] += kQuarter;
      matching.period_jump[into_v] =
          static_cast<std::uint8_t>((matching.period_jump[into_v] + 3) % 4);
      matching.period_jump[out_of_v] =
          static_cast<std::uint8_t>((matching.period_jump[out_of_v] + 1) % 4);
      --vertex_index[v];
      ++vertex_index[c.to_vertex[out_of_v]];
    }
  }
}

std::vector<Singularity> singularities(const Connectivity& c, const std::vector<int>& index) {
  std::vector<Singularity> result;
  for (Index v = 0; v < index.size(); ++v) {
    if (index[v] == 0) continue;
    const int regular_valence = c.is_boundary_vertex(v) ? 2 : 4;
    result.push_back({v, index[v] / 4.0, regular_valence - index[v]});
  }
  return result;
}

}  // namespace tessera
