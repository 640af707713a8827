#include "layout/metrics.h"

#include <cmath>
#include <numbers>
#include <utility>

namespace tessera::layout {

std::vector<double> corner_angles(const RefinedMesh& refined,
                                  const std::vector<std::int32_t>& patch,
                                  const LayoutCheck& check) {
  const Mesh& mesh = refined.mesh;
  // Per vertex, the corners at it as (patch, position in the result): a few at each node.
  std::vector<std::vector<std::pair<std::int32_t, std::size_t>>> corners_at(mesh.vertex_count());
  std::size_t count = 0;
  for (std::size_t p = 0; p < check.corners.size(); ++p)
    for (Index v : check.corners[p]) corners_at[v].emplace_back(std::int32_t(p), count++);
  std::vector<double> radians(count, 0.0);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index first = mesh.face_offsets[f];
    for (Index k = 0; k < 3; ++k)
      for (const auto& [p, slot] : corners_at[mesh.face_vertices[first + k]]) {
        if (p != patch[f]) continue;
        const Eigen::Vector2d& at = refined.uv[first + k];
        const Eigen::Vector2d a = refined.uv[first + (k + 1) % 3] - at;
        const Eigen::Vector2d b = refined.uv[first + (k + 2) % 3] - at;
        radians[slot] += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      }
  }
  std::vector<double> degrees(count);
  for (std::size_t k = 0; k < count; ++k) degrees[k] = radians[k] * 180 / std::numbers::pi;
  return degrees;
}

double relative_standard_deviation(const std::vector<double>& values) {
  if (values.size() < 2) return 0;
  double mean = 0;
  for (double x : values) mean += x / double(values.size());
  double variance = 0;
  for (double x : values) variance += (x - mean) * (x - mean) / double(values.size());
  return mean == 0 ? 0 : 100 * std::sqrt(variance) / std::abs(mean);
}

}  // namespace tessera::layout
