#include "mesh/symmetry.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "mesh/geometry.h"

namespace tessera {

namespace {

// Vertices hashed into cells of the tolerance's size; a point is matched against the 27 cells
// around its own.
class VertexGrid {
 public:
  VertexGrid(const Mesh& mesh, double cell) : mesh_(mesh), cell_(cell) {
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      cells_[key(cell_of(mesh.positions[v]))].push_back(v);
  }

  bool has_vertex_near(const Eigen::Vector3d& p, double tolerance) const {
    const Eigen::Vector3i c = cell_of(p);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it == cells_.end()) continue;
          for (Index v : it->second)
            if ((mesh_.positions[v] - p).norm() <= tolerance) return true;
        }
    return false;
  }

 private:
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    return (p / cell_).array().floor().cast<int>();
  }
  static std::uint64_t key(const Eigen::Vector3i& c) {
    auto part = [](int x) {
      return static_cast<std::uint64_t>(static_cast<std::uint32_t>(x) & 0x1FFFFFu);
    };
    return part(c.x()) | part(c.y()) << 21 | part(c.z()) << 42;
  }

  const Mesh& mesh_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<Index>> cells_;
};

}  // namespace

std::vector<bool> keeps_vertex_set(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& rotations,
                                   double relative_tolerance) {
  const double tolerance = relative_tolerance * bounding_box(mesh).diagonal();
  std::vector<bool> keeps;
  if (!(tolerance > 0.0)) {
    keeps.assign(rotations.size(), mesh.vertex_count() <= 1);
    return keeps;
  }
  const VertexGrid grid(mesh, tolerance);
  for (const Eigen::Matrix3d& r : rotations) {
    bool all = true;
    for (Index v = 0; v < mesh.vertex_count() && all; ++v)
      all = grid.has_vertex_near(r * mesh.positions[v], tolerance);
    keeps.push_back(all);
  }
  return keeps;
}

}  // namespace tessera
