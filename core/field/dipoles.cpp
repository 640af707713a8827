#include "field/dipoles.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "field/field_topology.h"

namespace tessera {
namespace {

constexpr double kQuarter = std::numbers::pi / 2;

// delta_h of halfedge h for the stored period jump: theta_j = theta_i + kappa_h - p_h pi/2 +
// delta_h (cross_field.h), reduced to [-pi, pi].
double turn(const Connectivity& c, const CrossField& field, Index h) {
  const double mismatch = field.angle[c.face[h]] + field.kappa[h] - field.angle[c.face[c.twin[h]]];
  return std::remainder(field.period_jump[h] * kQuarter - mismatch, 2 * std::numbers::pi);
}

}  // namespace

DipoleRematching cancel_adjacent_dipoles(const Connectivity& c, CrossField field,
                                         const std::vector<std::uint8_t>& edges) {
  // Raising p_h by one raises delta_h by pi/2: the index of h's head (which sums delta_h,
  // field_topology.cpp) grows by 1/4, that of its tail (which sums delta of the twin) drops by
  // 1/4. So the raised halfedge runs from the index-1/4 end to the index-(-1/4) end.
  std::vector<std::tuple<double, Index>> candidates;  // (new |delta|, halfedge raised)
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (!edges[e] || c.is_boundary_edge(e)) continue;
    Index h = c.edge_halfedge[e];
    if (field.vertex_index[c.to_vertex[h]] != -1) h = c.twin[h];
    if (field.vertex_index[c.from_vertex(h)] != 1 || field.vertex_index[c.to_vertex[h]] != -1)
      continue;
    candidates.emplace_back(std::abs(turn(c, field, h) + kQuarter), h);
  }
  std::sort(candidates.begin(), candidates.end());
  DipoleRematching result;
  std::size_t remaining = field.singularities.size();
  for (const auto& [changed, h] : candidates) {
    const Index tail = c.from_vertex(h);
    const Index head = c.to_vertex[h];
    if (field.vertex_index[tail] != 1 || field.vertex_index[head] != -1 || remaining == 2) continue;
    field.period_jump[h] = static_cast<std::uint8_t>((field.period_jump[h] + 1) % 4);
    field.period_jump[c.twin[h]] = static_cast<std::uint8_t>((4 - field.period_jump[h]) % 4);
    field.vertex_index[tail] = 0;
    field.vertex_index[head] = 0;
    remaining -= 2;
    ++result.cancelled;
  }
  field.singularities = singularities(c, field.vertex_index);
  result.field = std::move(field);
  return result;
}

}  // namespace tessera
