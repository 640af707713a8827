#include "param/injectivity.h"

#include <algorithm>
#include <array>
#include <memory>
#include <numeric>

#include <glpk.h>

namespace tessera {
namespace {

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Compressed lists: the items of entry i are items[offsets[i] .. offsets[i+1]).
struct Adjacency {
  std::vector<Index> offsets{0};
  std::vector<Index> items;
  std::span<const Index> of(Index i) const {
    return {items.data() + offsets[i], offsets[i + 1] - offsets[i]};
  }
};

// Builds an adjacency from (key, item) pairs with keys in [0, keys).
Adjacency invert(std::size_t keys, const std::vector<std::pair<Index, Index>>& pairs) {
  Adjacency a;
  a.offsets.assign(keys + 1, 0);
  for (const auto& [key, item] : pairs) ++a.offsets[key + 1];
  std::partial_sum(a.offsets.begin(), a.offsets.end(), a.offsets.begin());
  a.items.resize(pairs.size());
  std::vector<Index> fill(a.offsets.begin(), a.offsets.end() - 1);
  for (const auto& [key, item] : pairs) a.items[fill[key]++] = item;
  return a;
}

Adjacency vertex_faces(const Mesh& mesh) {
  std::vector<std::pair<Index, Index>> pairs;
  for (Index f = 0; f < mesh.face_count(); ++f)
    for (Index v : mesh.face(f)) pairs.emplace_back(v, f);
  return invert(mesh.vertex_count(), pairs);
}

Adjacency wedge_faces(const PoissonProblem& p) {
  std::vector<std::pair<Index, Index>> pairs;
  for (Index f = 0; f < p.wedge.size(); ++f)
    for (Index w : p.wedge[f]) pairs.emplace_back(w, f);
  return invert(p.wedge_count, pairs);
}

// The wedges each unknown (column of the basis) moves.
Adjacency column_wedges(const Eigen::SparseMatrix<double>& basis) {
  std::vector<std::pair<Index, Index>> pairs;
  for (Eigen::Index j = 0; j < basis.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(basis, j); it; ++it)
      pairs.emplace_back(static_cast<Index>(j), static_cast<Index>(it.row() / 2));
  return invert(static_cast<std::size_t>(basis.cols()), pairs);
}

// The marked faces and all faces within `rings` vertex rings of them.
std::vector<std::uint8_t> grow_rings(const Mesh& mesh, const Adjacency& vertex_to_faces,
                                     std::vector<std::uint8_t> faces, int rings) {
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<std::uint8_t> grown = faces;
    for (Index f = 0; f < mesh.face_count(); ++f) {
      if (!faces[f]) continue;
      for (Index v : mesh.face(f))
        for (Index g : vertex_to_faces.of(v)) grown[g] = 1;
    }
    faces = std::move(grown);
  }
  return faces;
}

Index find_root(std::vector<Index>& parent, Index i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// c + sum a_j d_j over the changes d_j of the unknowns of one program (j local to the program);
// c is the value at the current unknowns. Working with changes keeps the program well scaled (the
// unknowns themselves are large parameter values whose contributions cancel).
struct LinearForm {
  double constant = 0;
  std::vector<std::pair<Index, double>> terms;
};

// Sorted by unknown, duplicates summed (GLPK refuses repeated entries in a row).
void merge_terms(std::vector<std::pair<Index, double>>& terms) {
  std::sort(terms.begin(), terms.end());
  std::vector<std::pair<Index, double>> merged;
  for (const auto& [j, a] : terms) {
    if (!merged.empty() && merged.back().first == j)
      merged.back().second += a;
    else
      merged.emplace_back(j, a);
  }
  terms = std::move(merged);
}

// The four coordinates of h grad(u, v) on face f, as forms in the changes of the program's
// unknowns (local[j] for basis column j, kNoIndex if held fixed): index 2 * coordinate + axis.
std::array<LinearForm, 4> gradient_forms(const PoissonProblem& p, const RowMajor& rows, Index f,
                                         const std::vector<Index>& local,
                                         const Eigen::VectorXd& y) {
  std::array<LinearForm, 4> forms;
  for (int corner = 0; corner < 3; ++corner) {
    const Eigen::Vector2d g = p.h * p.gradient[f][corner];
    for (int coordinate = 0; coordinate < 2; ++coordinate) {
      const Eigen::Index row = 2 * p.wedge[f][corner] + coordinate;
      for (RowMajor::InnerIterator it(rows, row); it; ++it) {
        const Index j = local[it.col()];
        for (int axis = 0; axis < 2; ++axis) {
          LinearForm& form = forms[2 * coordinate + axis];
          const double a = it.value() * g[axis];
          form.constant += a * y[it.col()];
          if (j != kNoIndex) form.terms.emplace_back(j, a);
        }
      }
    }
  }
  for (LinearForm& form : forms) merge_terms(form.terms);
  return forms;
}

// The constraint matrix of a program in GLPK's 1-based triplet form.
struct ProgramRows {
  std::vector<int> row{0}, column{0};
  std::vector<double> value{0};
  std::vector<double> lower;  // per row
  void add(const LinearForm& form, double scale, int extra_column, double lower_bound) {
    const int r = static_cast<int>(lower.size()) + 1;
    for (const auto& [j, a] : form.terms) {
      row.push_back(r);
      column.push_back(static_cast<int>(j) + 1);
      value.push_back(scale * a);
    }
    row.push_back(r);
    column.push_back(extra_column);
    value.push_back(1.0);
    lower.push_back(lower_bound);
  }
};

struct ProgramDeleter {
  void operator()(glp_prob* lp) const { glp_delete_prob(lp); }
};

// One linear program over the changes of the unknowns `columns` (basis columns) and the faces they
// touch; on success adds the changes to y.
bool solve_program(const PoissonProblem& p, const RowMajor& rows, const std::vector<Index>& columns,
                   const std::vector<Index>& faces, std::vector<Index>& local,
                   const InjectivityOptions& options, double mean_area, Eigen::VectorXd& y) {
  for (Index k = 0; k < columns.size(); ++k) local[columns[k]] = k;
  const int unknowns = static_cast<int>(columns.size());
  const int face_count = static_cast<int>(faces.size());
  const int first_residual = unknowns + 1;
  const int first_slack = first_residual + 4 * face_count;
  ProgramRows program;
  for (int k = 0; k < face_count; ++k) {
    const Index f = faces[k];
    const std::array<LinearForm, 4> g = gradient_forms(p, rows, f, local, y);
    const Eigen::Vector2d u = p.frame_u[f];
    const Eigen::Vector2d v(-u.y(), u.x());
    const std::array<Eigen::Vector2d, 2> target{u, v};
    // |residual| <= s as s - residual >= 0 and s + residual >= 0.
    for (int q = 0; q < 4; ++q) {
      const double residual0 = g[q].constant - target[q / 2][q % 2];
      program.add(g[q], -1.0, first_residual + 4 * k + q, residual0);
      program.add(g[q], 1.0, first_residual + 4 * k + q, -residual0);
    }
    // (6.2), (6.3): the bisectors u +- v for grad u, v +- u for grad v.
    const std::array<std::pair<int, Eigen::Vector2d>, 4> bisectors{
        {{0, u + v}, {0, u - v}, {1, u + v}, {1, v - u}}};
    for (int b = 0; b < 4; ++b) {
      const auto& [coordinate, direction] = bisectors[b];
      LinearForm form;
      for (int axis = 0; axis < 2; ++axis) {
        const LinearForm& part = g[2 * coordinate + axis];
        form.constant += direction[axis] * part.constant;
        for (const auto& [j, a] : part.terms) form.terms.emplace_back(j, direction[axis] * a);
      }
      merge_terms(form.terms);
      program.add(form, 1.0, first_slack + 4 * k + b, options.margin - form.constant);
    }
  }

  std::unique_ptr<glp_prob, ProgramDeleter> lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MIN);
  const int column_count = unknowns + 8 * face_count;
  glp_add_cols(lp.get(), column_count);
  for (int j = 1; j <= column_count; ++j) {
    if (j < first_residual) {
      glp_set_col_bnds(lp.get(), j, GLP_FR, 0, 0);
    } else {
      glp_set_col_bnds(lp.get(), j, GLP_LO, 0, 0);
      const int k = (j < first_slack ? j - first_residual : j - first_slack) / 4;
      glp_set_obj_coef(lp.get(), j,
                       j < first_slack ? p.area[faces[k]] / mean_area : options.slack_weight);
    }
  }
  glp_add_rows(lp.get(), static_cast<int>(program.lower.size()));
  for (int r = 0; r < static_cast<int>(program.lower.size()); ++r)
    glp_set_row_bnds(lp.get(), r + 1, GLP_LO, program.lower[r], 0);
  glp_load_matrix(lp.get(), static_cast<int>(program.value.size()) - 1, program.row.data(),
                  program.column.data(), program.value.data());
  glp_smcp parameters;
  glp_init_smcp(&parameters);
  parameters.msg_lev = GLP_MSG_OFF;
  // GLPK's presolver misjudges these small programs now and then (reports no dual feasible
  // solution); the standard starting basis of the plain simplex is always valid here.
  parameters.presolve = GLP_OFF;
  const bool solved =
      glp_simplex(lp.get(), &parameters) == 0 && glp_get_status(lp.get()) == GLP_OPT;
  if (solved)
    for (int k = 0; k < unknowns; ++k) y[columns[k]] += glp_get_col_prim(lp.get(), k + 1);
  for (Index column : columns) local[column] = kNoIndex;
  return solved;
}

// Whether face f breaks one of (6.2), (6.3) with the margin.
bool violates_bisectors(const PoissonProblem& p, const Eigen::VectorXd& x, Index f, double margin) {
  Eigen::Vector2d grad_u = Eigen::Vector2d::Zero();
  Eigen::Vector2d grad_v = Eigen::Vector2d::Zero();
  for (int i = 0; i < 3; ++i) {
    grad_u += p.h * x[2 * p.wedge[f][i]] * p.gradient[f][i];
    grad_v += p.h * x[2 * p.wedge[f][i] + 1] * p.gradient[f][i];
  }
  const Eigen::Vector2d u = p.frame_u[f];
  const Eigen::Vector2d v(-u.y(), u.x());
  return std::min({grad_u.dot(u + v), grad_u.dot(u - v), grad_v.dot(u + v), grad_v.dot(v - u)}) <
         margin;
}

}  // namespace

std::vector<std::uint8_t> flipped_faces(const PoissonProblem& p, const Eigen::VectorXd& x) {
  std::vector<std::uint8_t> flipped(p.wedge.size(), 0);
  for (Index f = 0; f < p.wedge.size(); ++f) {
    const auto& w = p.wedge[f];
    const Eigen::Vector2d a(x[2 * w[0]], x[2 * w[0] + 1]);
    const Eigen::Vector2d b(x[2 * w[1]], x[2 * w[1] + 1]);
    const Eigen::Vector2d c(x[2 * w[2]], x[2 * w[2] + 1]);
    const Eigen::Vector2d ab = b - a;
    const Eigen::Vector2d ac = c - a;
    flipped[f] = ab.x() * ac.y() - ab.y() * ac.x() <= 0;
  }
  return flipped;
}

InjectivityReport enforce_bisector_constraints(const Mesh& mesh, const PoissonProblem& p,
                                               const Eigen::SparseMatrix<double>& basis,
                                               const std::vector<std::uint8_t>& singular_ring,
                                               const InjectivityOptions& options,
                                               Eigen::VectorXd& y, const Progress& progress) {
  glp_term_out(GLP_OFF);
  InjectivityReport report;
  const RowMajor rows = basis;
  const Adjacency vertex_to_faces = vertex_faces(mesh);
  const Adjacency wedge_to_faces = wedge_faces(p);
  const Adjacency column_to_wedges = column_wedges(basis);
  const double mean_area =
      std::accumulate(p.area.begin(), p.area.end(), 0.0) / std::max<std::size_t>(1, p.area.size());
  std::vector<Index> local(static_cast<std::size_t>(basis.cols()), kNoIndex);

  for (int round = 0; round < options.rounds; ++round) {
    progress.step("injectivity", static_cast<double>(round) / options.rounds);
    const Eigen::VectorXd x = basis * y;
    std::vector<std::uint8_t> constrained = flipped_faces(p, x);
    // Round 0 adds the ring triangles outside the bisectors; the next rounds retry the flipped
    // triangles, the last ones only those away from singularities (a ring triangle that bigger
    // programs could not unflip rarely gets there with more room, at a high price).
    for (Index f = 0; f < constrained.size(); ++f) {
      if (round == 0)
        constrained[f] |= singular_ring[f] && violates_bisectors(p, x, f, options.margin);
      else if (round >= options.ring_rounds)
        constrained[f] &= !singular_ring[f];
    }
    const auto count =
        static_cast<std::size_t>(std::count(constrained.begin(), constrained.end(), 1));
    if (count == 0) break;
    ++report.rounds;
    report.constrained_faces += count;

    // Unknowns that move a triangle of the grown region, and not too many triangles, are freed:
    // wedge positions, and the translations of short cut arcs between close singularities.
    const std::vector<std::uint8_t> region =
        grow_rings(mesh, vertex_to_faces, std::move(constrained), round);
    std::vector<std::uint8_t> movable(static_cast<std::size_t>(basis.cols()), 0);
    for (Index j = 0; j < movable.size(); ++j) {
      std::size_t moved = 0;
      bool touches = false;
      for (Index w : column_to_wedges.of(j))
        for (Index f : wedge_to_faces.of(w)) {
          ++moved;
          touches |= region[f] != 0;
        }
      movable[j] = touches && moved <= (options.column_faces << (2 * std::min(round, 2)));
    }
    // Unknowns that share a face belong to one program.
    std::vector<Index> parent(movable.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<Index> face_column(mesh.face_count(), kNoIndex);
    for (Index j = 0; j < movable.size(); ++j) {
      if (!movable[j]) continue;
      for (Index w : column_to_wedges.of(j))
        for (Index f : wedge_to_faces.of(w)) {
          if (face_column[f] == kNoIndex)
            face_column[f] = j;
          else
            parent[find_root(parent, j)] = find_root(parent, face_column[f]);
        }
    }
    std::vector<std::vector<Index>> program_columns(movable.size());
    std::vector<std::vector<Index>> program_faces(movable.size());
    for (Index j = 0; j < movable.size(); ++j)
      if (movable[j]) program_columns[find_root(parent, j)].push_back(j);
    for (Index f = 0; f < mesh.face_count(); ++f)
      if (face_column[f] != kNoIndex) program_faces[find_root(parent, face_column[f])].push_back(f);
    for (Index root = 0; root < movable.size(); ++root) {
      if (program_columns[root].empty()) continue;
      if (program_faces[root].size() > options.max_program_faces) {
        ++report.skipped_programs;
        continue;
      }
      ++report.programs;
      if (!solve_program(p, rows, program_columns[root], program_faces[root], local, options,
                         mean_area, y))
        ++report.unsolved_programs;
    }
  }
  progress.step("injectivity", 1);
  return report;
}

}  // namespace tessera
