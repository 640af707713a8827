// Geometric symmetry of a mesh: the rotations of a torus about its axis by its segment angle keep
// its vertices, half of that does not.
#include <gtest/gtest.h>

#include <numbers>

#include <Eigen/Geometry>

#include "mesh/shapes.h"
#include "mesh/symmetry.h"

namespace tessera {
namespace {

TEST(MeshSymmetry, TorusRotations) {
  const Mesh mesh = torus(2.0, 0.5, 48, 24);
  const double step = 2 * std::numbers::pi / 48;
  const std::vector<Eigen::Matrix3d> rotations = {
      Eigen::Matrix3d::Identity(),
      Eigen::AngleAxisd(step, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
      Eigen::AngleAxisd(step / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
      Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix(),
      Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix()};
  EXPECT_EQ(keeps_vertex_set(mesh, rotations), (std::vector<bool>{true, true, false, true, false}));
}

}  // namespace
}  // namespace tessera
