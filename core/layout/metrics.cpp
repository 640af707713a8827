#include "layout/metrics.h"

#include <cmath>
#include <map>
#include <numbers>

namespace tessera::layout {

std::vector<double> corner_angles(const RefinedMesh& refined,
                                  const std::vector<std::int32_t>& patch,
                                  const LayoutCheck& check) {
  const Mesh& mesh = refined.mesh;
  std::map<std::pair<std::int32_t, Index>, double> angle;  // (patch, corner vertex) -> radians
  for (std::size_t p = 0; p < check.corners.size(); ++p)
    for (Index v : check.corners[p]) angle[{std::int32_t(p), v}] = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index first = mesh.face_offsets[f];
    for (Index k = 0; k < 3; ++k) {
      auto found = angle.find({patch[f], mesh.face_vertices[first + k]});
      if (found == angle.end()) continue;
      const Eigen::Vector2d& at = refined.uv[first + k];
      const Eigen::Vector2d a = refined.uv[first + (k + 1) % 3] - at;
      const Eigen::Vector2d b = refined.uv[first + (k + 2) % 3] - at;
      found->second += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  }
  std::vector<double> degrees;
  for (std::size_t p = 0; p < check.corners.size(); ++p)
    for (Index v : check.corners[p])
      degrees.push_back(angle[{std::int32_t(p), v}] * 180 / std::numbers::pi);
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
