#include "param/seamless_param.h"

#include <chrono>
#include <cmath>
#include <numeric>

#include <Eigen/SparseCholesky>

#include "base/error.h"
#include "field/cut_graph.h"
#include "mesh/geometry.h"
#include "param/poisson.h"
#include "param/seams.h"
#include "param/wedges.h"

namespace tessera {
namespace {

class StepTimer {
 public:
  explicit StepTimer(std::vector<StepTime>& times) : times_(times) {}
  void finish(const std::string& step) {
    const auto now = std::chrono::steady_clock::now();
    times_.push_back({step, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  std::vector<StepTime>& times_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Per face 1 if one of its vertices is singular.
std::vector<std::uint8_t> singular_rings(const Mesh& mesh, const CrossField& field) {
  std::vector<std::uint8_t> ring(mesh.face_count(), 0);
  for (Index f = 0; f < mesh.face_count(); ++f)
    for (Index v : mesh.face(f)) ring[f] |= field.vertex_index[v] != 0;
  return ring;
}

std::vector<Eigen::Vector2d> corner_uv(const Wedges& wedges, const Eigen::VectorXd& x) {
  std::vector<Eigen::Vector2d> uv(wedges.corner_wedge.size());
  for (Index c = 0; c < uv.size(); ++c)
    uv[c] = {x[2 * wedges.corner_wedge[c]], x[2 * wedges.corner_wedge[c] + 1]};
  return uv;
}

double bounding_diagonal(const std::vector<Eigen::Vector2d>& points) {
  if (points.empty()) return 0;
  Eigen::Vector2d low = points.front();
  Eigen::Vector2d high = points.front();
  for (const Eigen::Vector2d& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (high - low).norm();
}

// A closed surface without singularities is a torus (Poincare-Hopf); a seamless parameterization
// makes it a flat torus, whose charts only translate around its loops. A field that turns by
// quarter turns around a loop (nonzero rotation across a cut edge) admits none.
void check_flat_holonomy(const Connectivity& c, const CrossField& field, const CrossField& combed,
                         const std::vector<std::uint8_t>& cut) {
  if (!field.singularities.empty() || c.halfedge_count() != c.corner_count) return;
  for (Index e = 0; e < c.edge_count(); ++e)
    if (cut[e] && combed.period_jump[c.edge_halfedge[e]] != 0)
      throw InputError(
          "the cross field has no singularities but turns by a quarter turn around a loop of the "
          "torus, so no seamless parameterization exists; use a field aligned to the principal "
          "curvature directions (--align curvature) or one with singularities");
}

}  // namespace

SeamlessParam seamless_parameterization(const Mesh& mesh, const Connectivity& c,
                                        const FaceFrames& frames, const CrossField& field,
                                        const ParamOptions& options, const Progress& progress) {
  if (!(options.h_relative > 0) || !std::isfinite(options.h_relative))
    throw InputError("the relative sizing h must be a positive number, got " +
                     std::to_string(options.h_relative));
  SeamlessParam param;
  StepTimer timer(param.seconds);
  param.h = options.h_relative * bounding_box(mesh).diagonal();
  param.singularities = field.singularities;

  progress.step("cut graph", 0);
  const DualTree tree = dual_spanning_tree(c, field);
  const CrossField combed = comb(c, frames, field, tree);
  param.cut = cut_graph(c, combed, tree);
  check_flat_holonomy(c, field, combed, param.cut);
  const Wedges wedges = cut_wedges(c, param.cut);
  timer.finish("cut graph");

  progress.step("assembly", 0);
  const PoissonProblem problem = poisson_problem(mesh, frames, combed, wedges, param.h);
  const Eigen::SparseMatrix<double> basis = seam_basis(mesh, c, combed, param.cut, wedges);
  const Eigen::SparseMatrix<double> basis_t = basis.transpose();
  const Eigen::SparseMatrix<double> reduced = basis_t * poisson_matrix(problem) * basis;
  const Eigen::VectorXd rhs = basis_t * poisson_rhs(problem);
  timer.finish("assembly");

  progress.step("solve", 0);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(reduced);
  if (solver.info() != Eigen::Success)
    throw Error("the parameterization system could not be factorized (sparse LDLT failed)");
  Eigen::VectorXd y = solver.solve(rhs);
  const std::vector<std::uint8_t> before = flipped_faces(problem, basis * y);
  param.flipped_before_injectivity = std::accumulate(before.begin(), before.end(), std::size_t{0});
  timer.finish("solve");

  const std::vector<std::uint8_t> ring = singular_rings(mesh, field);
  param.injectivity =
      enforce_bisector_constraints(mesh, problem, basis, ring, options.injectivity, y, progress);
  timer.finish("injectivity");

  const Eigen::VectorXd x = basis * y;
  param.uv = corner_uv(wedges, x);
  const Transitions transitions = seam_transitions(c, combed, param.cut, param.uv);
  param.rotation = transitions.rotation;
  param.translation = transitions.translation;
  const double domain = bounding_diagonal(param.uv);
  param.max_seam_error = domain > 0 ? transitions.max_error / domain : 0;
  const std::vector<std::uint8_t> flipped = flipped_faces(problem, x);
  for (Index f = 0; f < flipped.size(); ++f) {
    param.flipped_triangles += flipped[f];
    param.flipped_outside_singular_rings += flipped[f] && !ring[f];
  }
  const double area = std::accumulate(frames.area.begin(), frames.area.end(), 0.0);
  param.energy = poisson_energy(problem, x) / area;
  progress.step("injectivity", 1);
  return param;
}

}  // namespace tessera
