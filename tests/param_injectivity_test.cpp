// The bisector constraints (core/param/injectivity, Sec. 6.5, (6.2), (6.3)): a parameterization
// with a folded vertex is unfolded by the GLPK programs, and a valid one is left alone.
#include <gtest/gtest.h>

#include <numeric>

#include <Eigen/SparseCholesky>

#include "field/cut_graph.h"
#include "field/design.h"
#include "mesh/shapes.h"
#include "param/injectivity.h"
#include "param/seams.h"

namespace tessera {
namespace {

struct Solved {
  Mesh mesh;
  PoissonProblem problem;
  Eigen::SparseMatrix<double> basis;
  Eigen::VectorXd y;
  Wedges wedges;
  std::vector<std::uint8_t> cut;
  std::vector<std::uint8_t> no_rings;
};

Solved solve(Mesh mesh) {
  Solved s{std::move(mesh), {}, {}, {}, {}, {}, {}};
  const Connectivity c = build_connectivity(s.mesh);
  const FaceFrames frames = face_frames(s.mesh);
  const CrossField field = design_cross_field(s.mesh, c, frames, {}, Progress());
  const DualTree tree = dual_spanning_tree(c, field);
  const CrossField combed = comb(c, frames, field, tree);
  s.cut = cut_graph(c, combed, tree);
  s.wedges = cut_wedges(c, s.cut);
  s.problem = poisson_problem(s.mesh, frames, combed, s.wedges, 0.05);
  s.basis = seam_basis(s.mesh, c, combed, s.cut, s.wedges);
  const Eigen::SparseMatrix<double> bt = s.basis.transpose();
  const Eigen::SparseMatrix<double> reduced = bt * poisson_matrix(s.problem) * s.basis;
  s.y = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(reduced).solve(bt *
                                                                          poisson_rhs(s.problem));
  s.no_rings.assign(s.mesh.face_count(), 0);
  return s;
}

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// The unknown that is exactly u of wedge w, or -1 if u of w is a combination.
Eigen::Index own_unknown(const RowMajor& rows, Index w) {
  RowMajor::InnerIterator it(rows, 2 * w);
  if (!it || it.value() != 1.0) return -1;
  const Eigen::Index column = it.col();
  return ++it ? -1 : column;
}

std::size_t count_flipped(const Solved& s) {
  const std::vector<std::uint8_t> flipped = flipped_faces(s.problem, s.basis * s.y);
  return std::accumulate(flipped.begin(), flipped.end(), std::size_t{0});
}

TEST(Injectivity, UnfoldsAFoldedVertex) {
  Solved s = solve(icosphere(3));
  ASSERT_EQ(count_flipped(s), 0u);
  // A wedge that is its own unknown (a vertex off the cut): drag it across its neighbours.
  const RowMajor rows = s.basis;
  Eigen::Index column = -1;
  for (Index w = 0; w < s.wedges.count && column < 0; ++w) column = own_unknown(rows, w);
  ASSERT_GE(column, 0);
  s.y[column] += 3.0;  // about three edge lengths in parameter units
  const std::size_t folded = count_flipped(s);
  ASSERT_GT(folded, 0u);

  const InjectivityReport report = enforce_bisector_constraints(
      s.mesh, s.problem, s.basis, s.no_rings, InjectivityOptions(), s.y, Progress());
  EXPECT_GE(report.programs, 1u);
  EXPECT_EQ(report.unsolved_programs, 0u);
  EXPECT_EQ(count_flipped(s), 0u);
}

TEST(Injectivity, LeavesAValidParameterizationAlone) {
  Solved s = solve(icosphere(2));
  const Eigen::VectorXd before = s.y;
  const InjectivityReport report = enforce_bisector_constraints(
      s.mesh, s.problem, s.basis, s.no_rings, InjectivityOptions(), s.y, Progress());
  EXPECT_EQ(report.rounds, 0u);
  EXPECT_EQ(s.y, before);
}

}  // namespace
}  // namespace tessera
