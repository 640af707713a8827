#include "field/design.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "base/error.h"
#include "field/alignment.h"
#include "field/smoothest.h"
#include "mesh/topology.h"

namespace tessera {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// Shift that makes the smoothness matrix of an unconstrained component definite for the inverse
// iteration; far below the smallest eigenvalues of any mesh Tessera handles.
constexpr double kShift = 1e-8;

Eigen::Vector2d power(double angle) {
  return {std::cos(4 * angle), std::sin(4 * angle)};
}

Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d r;
  r << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return r;
}

// |e| / (distance of the barycentres across e) = 3 |e|^2 / (2 (A_f + A_g)).
double edge_weight(const Mesh& mesh, const Connectivity& c, const FaceFrames& frames, Index h) {
  const double length2 = halfedge_vector(mesh, c, h).squaredNorm();
  return 1.5 * length2 / (frames.area[c.face[h]] + frames.area[c.face[c.twin[h]]]);
}

// The linear system over the free faces (two real unknowns each, the power representation).
struct PowerSystem {
  std::vector<Index> row;    // per face, the first of its two rows; kNoIndex for a fixed face
  std::vector<double> mass;  // per face, A_T / total area
  SparseMatrix matrix;
  Eigen::VectorXd rhs;
};

struct SystemInputs {
  const FaceConstraints& constraints;
  const std::vector<std::complex<double>>& targets;  // empty without curvature term
  double target_weight;
  const std::vector<std::uint8_t>& shifted;  // per face: in a component solved by iteration
};

PowerSystem assemble(const Mesh& mesh, const Connectivity& c, const FaceFrames& frames,
                     const std::vector<double>& kappa, const SystemInputs& in) {
  PowerSystem s;
  const std::size_t faces = mesh.face_count();
  s.row.assign(faces, kNoIndex);
  Index rows = 0;
  double area_sum = 0;
  for (Index f = 0; f < faces; ++f) {
    area_sum += frames.area[f];
    if (!in.constraints.fixed[f]) {
      s.row[f] = rows;
      rows += 2;
    }
  }
  s.mass.resize(faces);
  for (Index f = 0; f < faces; ++f) s.mass[f] = frames.area[f] / area_sum;
  s.rhs = Eigen::VectorXd::Zero(rows);
  Triplets triplets;
  auto add_block = [&](Index a, Index b, const Eigen::Matrix2d& block) {
    if (s.row[a] == kNoIndex) return;
    if (s.row[b] == kNoIndex) {
      s.rhs.segment<2>(s.row[a]) -= block * power(in.constraints.angle[b]);
      return;
    }
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) triplets.emplace_back(s.row[a] + i, s.row[b] + j, block(i, j));
  };
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (c.is_boundary_edge(e)) continue;
    const Index h = c.edge_halfedge[e];
    const Index f = c.face[h];
    const Index g = c.face[c.twin[h]];
    // w |z_g - R z_f|^2 with R the transport of the power representation from f to g.
    const double w = edge_weight(mesh, c, frames, h);
    const Eigen::Matrix2d r = rotation(4 * kappa[h]);
    add_block(f, f, w * Eigen::Matrix2d::Identity());
    add_block(g, g, w * Eigen::Matrix2d::Identity());
    add_block(g, f, -w * r);
    add_block(f, g, -w * r.transpose());
  }
  for (Index f = 0; f < faces; ++f) {
    if (s.row[f] == kNoIndex) continue;
    const double diagonal = (in.target_weight + (in.shifted[f] ? kShift : 0.0)) * s.mass[f];
    for (int i = 0; i < 2; ++i) triplets.emplace_back(s.row[f] + i, s.row[f] + i, diagonal);
    if (!in.targets.empty()) {
      const std::complex<double> t = in.targets[f];
      s.rhs.segment<2>(s.row[f]) +=
          in.target_weight * s.mass[f] * Eigen::Vector2d(t.real(), t.imag());
    }
  }
  s.matrix.resize(rows, rows);
  s.matrix.setFromTriplets(triplets.begin(), triplets.end());
  return s;
}

// Components of the mesh that have no constraint and no curvature term: their field is the
// smoothest one (smallest eigenvector), not the solution of a linear system with a right-hand side.
std::vector<std::uint8_t> unconstrained_faces(const Mesh& mesh, const Connectivity& c,
                                              const FaceConstraints& constraints, bool has_target) {
  std::vector<std::uint8_t> result(mesh.face_count(), 0);
  if (has_target) return result;
  const Components components = connected_components(mesh, c);
  std::vector<std::uint8_t> constrained(components.count, 0);
  for (Index f = 0; f < mesh.face_count(); ++f)
    if (constraints.fixed[f]) constrained[components.face_component[f]] = 1;
  for (Index f = 0; f < mesh.face_count(); ++f)
    result[f] = !constrained[components.face_component[f]];
  return result;
}

// The first rows of the faces in `active`, grouped by connected component.
std::vector<std::vector<Index>> component_rows(const Mesh& mesh, const Connectivity& c,
                                               const PowerSystem& s,
                                               const std::vector<std::uint8_t>& active) {
  const Components components = connected_components(mesh, c);
  std::vector<std::vector<Index>> rows(components.count);
  for (Index f = 0; f < s.row.size(); ++f)
    if (active[f]) rows[components.face_component[f]].push_back(s.row[f]);
  return rows;
}

}  // namespace

CrossField design_cross_field(const Mesh& mesh, const Connectivity& c, const FaceFrames& frames,
                              const FieldOptions& options, const Progress& progress) {
  if (!(options.sharp_degrees > 0))
    throw InputError("the sharp-edge angle must be positive (degrees), got " +
                     std::to_string(options.sharp_degrees));
  if (!(options.curvature_weight > 0) && options.align == FieldAlignment::curvature)
    throw InputError("the curvature blend weight must be positive, got " +
                     std::to_string(options.curvature_weight));
  progress.step("field", 0);
  const std::vector<double> kappa = connection_angles(mesh, c, frames);
  const FaceConstraints constraints =
      feature_constraints(mesh, c, frames, kappa, options.sharp_degrees * std::numbers::pi / 180);
  const bool curvature = options.align == FieldAlignment::curvature;
  const std::vector<std::complex<double>> targets =
      curvature ? curvature_targets(mesh, frames) : std::vector<std::complex<double>>{};
  const std::vector<std::uint8_t> unconstrained =
      unconstrained_faces(mesh, c, constraints, curvature);
  const PowerSystem s =
      assemble(mesh, c, frames, kappa,
               {constraints, targets, curvature ? options.curvature_weight : 0.0, unconstrained});
  progress.step("field", 0.1);

  Eigen::SimplicialLDLT<SparseMatrix> solver(s.matrix);
  if (solver.info() != Eigen::Success)
    throw Error("the cross-field system could not be factorized (sparse LDLT failed)");
  progress.step("field", 0.3);
  Eigen::VectorXd z = solver.solve(s.rhs);
  bool any_unconstrained = false;
  for (std::uint8_t u : unconstrained) any_unconstrained |= u != 0;
  if (any_unconstrained) {
    Eigen::VectorXd mass(s.rhs.size());
    for (Index f = 0; f < s.row.size(); ++f)
      if (s.row[f] != kNoIndex) mass.segment<2>(s.row[f]).setConstant(s.mass[f]);
    z += smoothest_power_fields(s.matrix, solver, mass, component_rows(mesh, c, s, unconstrained),
                                progress);
  }

  std::vector<double> angle(mesh.face_count());
  for (Index f = 0; f < mesh.face_count(); ++f)
    angle[f] =
        s.row[f] == kNoIndex ? constraints.angle[f] : std::atan2(z[s.row[f] + 1], z[s.row[f]]) / 4;
  progress.step("field", 1);
  return cross_field_from_angles(mesh, c, frames, std::move(angle));
}

}  // namespace tessera
