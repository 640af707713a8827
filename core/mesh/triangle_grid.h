// A uniform grid over the triangles of a mesh (polygons fanned from their first corner), for the
// queries that look at triangles near each other: pairs of triangles whose bounding boxes overlap
// (self_intersection.h), the first triangle a ray meets (export/print_check.h) and the triangles
// near a point (remesh/smoothing.h).
//
// In:  a mesh with indices in range.
// Out: the triangles (corners, face, bounding box) and, per grid cell, the triangles whose
//      bounding boxes reach it. The cell size is about the mean triangle extent, at least the
//      bounding-box diagonal / 2^20, so that a cell's coordinates fit in 21 bits.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace tessera {

struct Box {
  Eigen::Vector3d lo, hi;
};

class TriangleGrid {
 public:
  using CellKey = std::uint64_t;
  using Cell = std::array<std::int64_t, 3>;
  static constexpr int kCellBits = 21;

  explicit TriangleGrid(const Mesh& mesh);

  std::size_t size() const { return corners.size(); }
  Cell cell_of(const Eigen::Vector3d& p) const;
  static CellKey key(const Cell& c);

  // Every pair of triangles whose bounding boxes overlap, once, as visit(s, t); `visit_cell`
  // after each cell (for progress: it is told the share of cells done).
  void for_each_overlapping_pair(const std::function<void(std::uint32_t, std::uint32_t)>& visit,
                                 const std::function<void(double)>& visit_cell) const;

  // The nearest triangle that the ray from `origin` along the unit vector `direction` meets within
  // `max_distance`, skipping triangles with the corner `skip` (the vertex the ray starts from):
  // {triangle, distance}, triangle kNoIndex if none.
  struct Hit {
    Index triangle = kNoIndex;
    double distance = std::numeric_limits<double>::infinity();
  };
  Hit first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                double max_distance, Index skip) const;

  // Every triangle whose bounding box reaches a cell that the cube of half-width `radius` around
  // `p` reaches, as visit(triangle) (a triangle in several such cells is visited once per cell).
  void for_each_triangle_near(const Eigen::Vector3d& p, double radius,
                              const std::function<void(std::uint32_t)>& visit) const;

  std::vector<std::array<Index, 3>> corners;  // per triangle, its mesh vertices
  std::vector<Index> face;                    // per triangle, its mesh face
  std::vector<Box> box;                       // per triangle

 private:
  const Mesh& mesh_;
  Eigen::Vector3d origin_;
  double cell_ = 1.0;
  std::unordered_map<CellKey, std::vector<std::uint32_t>> cells_;
};

}  // namespace tessera
