#include "matching/lp_relaxation.h"

#define GLP_UNDOC  // glp_gmi_gen(): GLPK 5.0 exports it; its manual leaves it out
#include <glpk.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "base/error.h"

namespace tessera::matching {

namespace {

constexpr double kFractional = 1e-6;    // x in (eps, 1 - eps) is fractional
constexpr double kCutTolerance = 1e-6;  // a row violated by less is not added
constexpr double kGomorySlack = 1e-7;   // a Gomory row's right-hand side, loosened by this much

void add_row(glp_prob* lp, const std::vector<int>& columns, int type, double bound) {
  const int row = glp_add_rows(lp, 1);
  glp_set_row_bnds(lp, row, type, bound, bound);
  std::vector<int> index(columns.size() + 1);
  std::vector<double> value(columns.size() + 1, 1.0);
  std::copy(columns.begin(), columns.end(), index.begin() + 1);
  glp_set_mat_row(lp, row, static_cast<int>(columns.size()), index.data(), value.data());
}

std::vector<int> columns_of(std::span<const std::uint32_t> edges) {
  std::vector<int> columns(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) columns[k] = static_cast<int>(edges[k]) + 1;
  return columns;
}

int simplex(glp_prob* lp, double cutoff, double seconds) {
  glp_smcp parameters;
  glp_init_smcp(&parameters);
  parameters.msg_lev = GLP_MSG_OFF;
  parameters.meth = GLP_DUALP;
  parameters.obj_ul = cutoff;
  parameters.tm_lim = static_cast<int>(std::min(std::max(seconds, 0.0) * 1000.0, 2.0e9)) + 1;
  return glp_simplex(lp, &parameters);
}

}  // namespace

void LpRelaxation::Deleter::operator()(glp_prob* p) const {
  glp_delete_prob(p);
}

LpRelaxation::LpRelaxation(const MatchingProblem& problem, const Adjacency& incident,
                           const std::vector<Clique>& cliques)
    : problem_(problem), lp_(glp_create_prob()) {
  glp_prob* lp = lp_.get();
  glp_set_obj_dir(lp, GLP_MIN);
  if (!problem.edges.empty()) glp_add_cols(lp, static_cast<int>(problem.edges.size()));
  for (std::size_t e = 0; e < problem.edges.size(); ++e) {
    glp_set_col_bnds(lp, static_cast<int>(e) + 1, GLP_DB, 0.0, 1.0);
    glp_set_obj_coef(lp, static_cast<int>(e) + 1, problem.edges[e].weight);
    glp_set_col_kind(lp, static_cast<int>(e) + 1, GLP_IV);  // for add_gomory_cuts()
  }
  for (std::uint32_t v = 0; v < problem.node_count(); ++v)  // (5.2)
    add_row(lp, columns_of(incident.of(v)), problem.is_virtual[v] ? GLP_UP : GLP_FX, 1.0);
  for (const Clique& clique : cliques) pool_.push_back({clique, 1.0, true});  // (5.3), lazily
  glp_std_basis(lp);
}

LpRelaxation::~LpRelaxation() = default;

void LpRelaxation::set_bounds(std::uint32_t e, int lower, int upper) {
  const int column = static_cast<int>(e) + 1;
  if (lower == upper) {
    glp_set_col_bnds(lp_.get(), column, GLP_FX, lower, upper);
  } else {
    glp_set_col_bnds(lp_.get(), column, GLP_DB, lower, upper);
  }
}

LpStatus LpRelaxation::solve(double cutoff, double seconds) {
  glp_prob* lp = lp_.get();
  int code = simplex(lp, cutoff, seconds);
  if (code == GLP_EFAIL || code == GLP_ESING || code == GLP_ECOND || code == GLP_EBADB) {
    glp_std_basis(lp);  // a basis gone numerically bad: start afresh once
    code = simplex(lp, cutoff, seconds);
  }
  if (code == GLP_EOBJUL) return LpStatus::cutoff;
  if (code == GLP_ETMLIM) return LpStatus::time_limit;
  if (code != 0)
    throw Error("GLPK's simplex failed on the relaxation (code " + std::to_string(code) + ")");
  const int status = glp_get_status(lp);
  if (status == GLP_NOFEAS) return LpStatus::infeasible;
  if (status != GLP_OPT)
    throw Error("GLPK's simplex ended without an optimum (status " + std::to_string(status) + ")");
  read_solution();
  return objective_ > cutoff ? LpStatus::cutoff : LpStatus::optimal;
}

LpStatus LpRelaxation::solve_with_cuts(const Adjacency& exclusion, double cutoff, double seconds,
                                       int rounds) {
  const auto start = std::chrono::steady_clock::now();
  const auto seconds_left = [&] {
    return seconds -
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  LpStatus status = solve(cutoff, seconds);
  int round = 0;
  while (status == LpStatus::optimal) {
    if (add_violated_pooled_rows() == 0) {
      if (round == rounds) break;
      ++round;
      const std::size_t odd_sets = add_violated_odd_sets();
      const std::vector<Clique> cliques = violated_cliques(exclusion, values_, kCutTolerance);
      if (odd_sets == 0 && cliques.empty()) break;
      add_cliques(cliques);
    }
    status = solve(cutoff, seconds_left());
  }
  return status;
}

std::vector<std::uint8_t> LpRelaxation::clique_row_marks() const {
  std::vector<std::uint8_t> is_clique(static_cast<std::size_t>(glp_get_num_rows(lp_.get())) + 1, 0);
  for (const auto& [row, clique] : clique_rows_) is_clique[static_cast<std::size_t>(row)] = 1;
  return is_clique;
}

std::vector<std::uint32_t> LpRelaxation::row_edges(int row) const {
  std::vector<int> index(
      static_cast<std::size_t>(glp_get_mat_row(lp_.get(), row, nullptr, nullptr)) + 1);
  const int length = glp_get_mat_row(lp_.get(), row, index.data(), nullptr);
  std::vector<std::uint32_t> edges;
  for (int k = 1; k <= length; ++k) edges.push_back(static_cast<std::uint32_t>(index[k] - 1));
  std::sort(edges.begin(), edges.end());
  return edges;
}

void LpRelaxation::drop_slack_rows() {
  glp_prob* lp = lp_.get();
  const int rows = glp_get_num_rows(lp);
  const int first_cut = static_cast<int>(problem_.node_count()) + 1;  // after the degree rows
  const std::vector<std::uint8_t> is_clique = clique_row_marks();
  std::vector<int> dropped{0};  // GLPK's 1-based list
  std::vector<int> new_number(static_cast<std::size_t>(rows) + 1, 0);
  int kept = 0;
  for (int i = 1; i <= rows; ++i) {
    const bool gomory = glp_get_row_type(lp, i) == GLP_LO;
    const double slack = gomory ? glp_get_row_prim(lp, i) - glp_get_row_lb(lp, i)
                                : glp_get_row_ub(lp, i) - glp_get_row_prim(lp, i);
    if (i < first_cut || glp_get_row_stat(lp, i) != GLP_BS || slack <= kCutTolerance) {
      new_number[static_cast<std::size_t>(i)] = ++kept;
      continue;
    }
    dropped.push_back(i);
    if (gomory) continue;  // dense, and derived once at the root: not kept in the pool
    PooledRow row;
    row.bound = glp_get_row_ub(lp, i);
    row.clique = is_clique[static_cast<std::size_t>(i)] != 0;
    row.edges = row_edges(i);
    pool_.push_back(std::move(row));
  }
  if (dropped.size() == 1) return;
  glp_del_rows(lp, static_cast<int>(dropped.size()) - 1, dropped.data());
  std::vector<std::pair<int, Clique>> clique_rows;
  for (auto& [row, clique] : clique_rows_)
    if (const int renumbered = new_number[static_cast<std::size_t>(row)]; renumbered > 0)
      clique_rows.emplace_back(renumbered, std::move(clique));
  clique_rows_ = std::move(clique_rows);
}

std::size_t LpRelaxation::add_violated_pooled_rows() {
  std::size_t added = 0;
  for (std::size_t k = 0; k < pool_.size();) {
    double sum = 0.0;
    for (std::uint32_t e : pool_[k].edges) sum += values_[e];
    if (sum <= pool_[k].bound + kCutTolerance) {
      ++k;
      continue;
    }
    if (pool_[k].clique) {
      add_clique_row(pool_[k].edges);
    } else {
      add_row(lp_.get(), columns_of(pool_[k].edges), GLP_UP, pool_[k].bound);
    }
    pool_[k] = std::move(pool_.back());
    pool_.pop_back();
    ++added;
  }
  return added;
}

void LpRelaxation::read_solution() {
  glp_prob* lp = lp_.get();
  const std::size_t m = problem_.edges.size();
  values_.resize(m);
  reduced_.resize(m);
  for (std::size_t e = 0; e < m; ++e) {
    values_[e] = glp_get_col_prim(lp, static_cast<int>(e) + 1);
    reduced_[e] = glp_get_col_dual(lp, static_cast<int>(e) + 1);
  }
  objective_ = glp_get_obj_val(lp);
}

void LpRelaxation::add_cliques(const std::vector<Clique>& cliques) {
  for (const Clique& clique : cliques) add_clique_row(clique);
}

void LpRelaxation::add_clique_row(const Clique& clique) {
  add_row(lp_.get(), columns_of(clique), GLP_UP, 1.0);
  clique_rows_.emplace_back(glp_get_num_rows(lp_.get()), clique);
}

std::vector<double> LpRelaxation::edge_prices() const {
  std::vector<double> prices(problem_.edges.size(), 0.0);
  for (const auto& [row, clique] : clique_rows_) {
    const double price = std::max(0.0, -glp_get_row_dual(lp_.get(), row));
    for (std::uint32_t e : clique) prices[e] += price;
  }
  return prices;
}

std::size_t LpRelaxation::add_violated_odd_sets() {
  // Components of the graph of fractional edges, by union-find over the nodes.
  std::vector<std::uint32_t> parent(problem_.node_count());
  for (std::uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
  auto find = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (std::size_t e = 0; e < values_.size(); ++e)
    if (values_[e] > kFractional && values_[e] < 1.0 - kFractional)
      parent[find(problem_.edges[e].u)] = find(problem_.edges[e].v);
  std::vector<std::uint32_t> size(parent.size(), 0);
  std::vector<std::uint8_t> has_virtual(parent.size(), 0);
  for (std::uint32_t v = 0; v < parent.size(); ++v) {
    ++size[find(v)];
    has_virtual[find(v)] |= problem_.is_virtual[v];
  }
  std::vector<std::vector<int>> rows(parent.size());
  for (std::size_t e = 0; e < problem_.edges.size(); ++e) {
    const std::uint32_t root = find(problem_.edges[e].u);
    if (root == find(problem_.edges[e].v) && size[root] % 2 == 1 && size[root] > 1 &&
        !has_virtual[root])
      rows[root].push_back(static_cast<int>(e) + 1);
  }
  std::size_t added = 0;
  for (std::uint32_t root = 0; root < rows.size(); ++root) {
    if (rows[root].empty()) continue;
    add_row(lp_.get(), rows[root], GLP_UP, (size[root] - 1) / 2.0);
    ++added;
  }
  return added;
}

std::size_t LpRelaxation::add_gomory_cuts(int max_cuts) {
  glp_prob* lp = lp_.get();
  if (!glp_bf_exists(lp) && glp_factorize(lp) != 0) return 0;
  std::unique_ptr<glp_prob, Deleter> cuts(glp_create_prob());
  glp_add_cols(cuts.get(), glp_get_num_cols(lp));
  const int made = glp_gmi_gen(lp, cuts.get(), max_cuts);
  std::vector<int> index(static_cast<std::size_t>(glp_get_num_cols(lp)) + 1);
  std::vector<double> value(index.size());
  for (int i = 1; i <= made; ++i) {
    const int length = glp_get_mat_row(cuts.get(), i, index.data(), value.data());
    const int row = glp_add_rows(lp, 1);
    glp_set_row_bnds(lp, row, GLP_LO, glp_get_row_lb(cuts.get(), i) - kGomorySlack, 0.0);
    glp_set_mat_row(lp, row, length, index.data(), value.data());
  }
  return static_cast<std::size_t>(made);
}

std::vector<DualRow> LpRelaxation::dual_rows() const {
  glp_prob* lp = lp_.get();
  const int rows = glp_get_num_rows(lp);
  const int first_cut = static_cast<int>(problem_.node_count()) + 1;
  const std::vector<std::uint8_t> is_clique = clique_row_marks();
  std::vector<DualRow> dual(static_cast<std::size_t>(first_cut - 1));
  for (std::uint32_t v = 0; v < dual.size(); ++v) {
    dual[v].node = v;
    dual[v].multiplier = glp_get_row_dual(lp, static_cast<int>(v) + 1);
  }
  for (int i = first_cut; i <= rows; ++i) {
    if (glp_get_row_type(lp, i) != GLP_UP) continue;  // a Gomory row
    DualRow row;
    row.kind = is_clique[static_cast<std::size_t>(i)] ? DualRowKind::clique : DualRowKind::odd_set;
    row.multiplier = glp_get_row_dual(lp, i);
    row.edges = row_edges(i);
    dual.push_back(std::move(row));
  }
  return dual;
}

LpBasis LpRelaxation::basis() const {
  glp_prob* lp = lp_.get();
  LpBasis b;
  b.rows.resize(static_cast<std::size_t>(glp_get_num_rows(lp)));
  b.columns.resize(static_cast<std::size_t>(glp_get_num_cols(lp)));
  for (std::size_t i = 0; i < b.rows.size(); ++i)
    b.rows[i] = static_cast<std::int8_t>(glp_get_row_stat(lp, static_cast<int>(i) + 1));
  for (std::size_t j = 0; j < b.columns.size(); ++j)
    b.columns[j] = static_cast<std::int8_t>(glp_get_col_stat(lp, static_cast<int>(j) + 1));
  return b;
}

void LpRelaxation::restore(const LpBasis& basis) {
  glp_prob* lp = lp_.get();
  const int rows = glp_get_num_rows(lp);
  for (int i = 1; i <= rows; ++i)  // rows added after the basis was stored: slack basic
    glp_set_row_stat(lp, i,
                     static_cast<std::size_t>(i) <= basis.rows.size() ? basis.rows[i - 1] : GLP_BS);
  for (std::size_t j = 0; j < basis.columns.size(); ++j)
    glp_set_col_stat(lp, static_cast<int>(j) + 1, basis.columns[j]);
}

}  // namespace tessera::matching
