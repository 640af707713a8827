#include "param/poisson.h"

namespace tessera {
namespace {

Eigen::Vector2d perpendicular(const Eigen::Vector2d& x) {
  return {-x.y(), x.x()};
}

}  // namespace

Eigen::Vector2d quarter_turns(const Eigen::Vector2d& x, int r) {
  switch (((r % 4) + 4) % 4) {
    case 1:
      return perpendicular(x);
    case 2:
      return -x;
    case 3:
      return -perpendicular(x);
    default:
      return x;
  }
}

PoissonProblem poisson_problem(const Mesh& mesh, const FaceFrames& frames, const CrossField& combed,
                               const Wedges& wedges, double h) {
  PoissonProblem p;
  const std::size_t faces = mesh.face_count();
  p.gradient.resize(faces);
  p.frame_u.resize(faces);
  p.area = frames.area;
  p.wedge.resize(faces);
  p.wedge_count = wedges.count;
  p.h = h;
  for (Index f = 0; f < faces; ++f) {
    const auto v = mesh.face(f);
    std::array<Eigen::Vector2d, 3> corner;
    for (int i = 0; i < 3; ++i) {
      corner[i] = frames.local(f, mesh.positions[v[i]] - mesh.positions[v[0]]);
      p.wedge[f][i] = wedges.corner_wedge[mesh.face_offsets[f] + i];
    }
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector2d opposite = corner[(i + 2) % 3] - corner[(i + 1) % 3];
      p.gradient[f][i] = perpendicular(opposite) / (2 * p.area[f]);
    }
    p.frame_u[f] = {std::cos(combed.angle[f]), std::sin(combed.angle[f])};
  }
  return p;
}

Eigen::SparseMatrix<double> poisson_matrix(const PoissonProblem& p) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(18 * p.area.size());
  for (Index f = 0; f < p.area.size(); ++f)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double q = p.area[f] * p.gradient[f][i].dot(p.gradient[f][j]);
        for (Index coordinate = 0; coordinate < 2; ++coordinate)
          triplets.emplace_back(2 * p.wedge[f][i] + coordinate, 2 * p.wedge[f][j] + coordinate, q);
      }
  const auto n = static_cast<Eigen::Index>(2 * p.wedge_count);
  Eigen::SparseMatrix<double> q(n, n);
  q.setFromTriplets(triplets.begin(), triplets.end());
  return q;
}

Eigen::VectorXd poisson_rhs(const PoissonProblem& p) {
  Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(2 * p.wedge_count));
  for (Index f = 0; f < p.area.size(); ++f) {
    const Eigen::Vector2d target_u = p.frame_u[f] / p.h;
    const Eigen::Vector2d target_v = perpendicular(target_u);
    for (int i = 0; i < 3; ++i) {
      b[2 * p.wedge[f][i]] += p.area[f] * p.gradient[f][i].dot(target_u);
      b[2 * p.wedge[f][i] + 1] += p.area[f] * p.gradient[f][i].dot(target_v);
    }
  }
  return b;
}

double poisson_energy(const PoissonProblem& p, const Eigen::VectorXd& x) {
  double energy = 0;
  for (Index f = 0; f < p.area.size(); ++f) {
    Eigen::Vector2d grad_u = Eigen::Vector2d::Zero();
    Eigen::Vector2d grad_v = Eigen::Vector2d::Zero();
    for (int i = 0; i < 3; ++i) {
      grad_u += x[2 * p.wedge[f][i]] * p.gradient[f][i];
      grad_v += x[2 * p.wedge[f][i] + 1] * p.gradient[f][i];
    }
    energy += p.area[f] * ((p.h * grad_u - p.frame_u[f]).squaredNorm() +
                           (p.h * grad_v - perpendicular(p.frame_u[f])).squaredNorm());
  }
  return energy;
}

}  // namespace tessera
