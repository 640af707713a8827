// The linear relaxation of P1 that bounds the exact solver's search, solved by GLPK's simplex
// method: the degree rows (5.2), the conflict pairs (5.3) as clique rows (cliques.h), odd-set rows
// x(E(S)) <= (|S| - 1) / 2 of the perfect matching polytope added when violated, 0 <= x <= 1.
// The branch-and-bound fixes columns and re-solves with the dual simplex method from the last
// basis, or from a stored one.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "matching/adjacency.h"
#include "matching/cliques.h"
#include "matching/dual_bound.h"
#include "matching/problem.h"

struct glp_prob;

namespace tessera::matching {

enum class LpStatus { optimal, infeasible, cutoff, time_limit };

// A simplex basis (GLPK's row and column statuses).
struct LpBasis {
  std::vector<std::int8_t> rows, columns;
};

class LpRelaxation {
 public:
  // The degree rows, and the clique rows of `cliques` in the pool (drop_slack_rows()):
  // solve_with_cuts() brings in those a solution violates. Most never bind: fertility's roots
  // end with 229 to 485 rows (224 of them degree rows) where all its cliques make 1,680. The
  // smaller LP pivots faster: P1 over 13 alphas of the slider took 44 % less time on bunny, 17 %
  // on rocker-arm, 9 % on fertility (whose alpha 0 took 20 % more: another search tree).
  LpRelaxation(const MatchingProblem& problem, const Adjacency& incident,
               const std::vector<Clique>& cliques);
  ~LpRelaxation();
  LpRelaxation(const LpRelaxation&) = delete;
  LpRelaxation& operator=(const LpRelaxation&) = delete;

  // Column e in [lower, upper] (each 0 or 1).
  void set_bounds(std::uint32_t e, int lower, int upper);

  double objective() const { return objective_; }
  const std::vector<double>& values() const { return values_; }          // x per edge
  const std::vector<double>& reduced_costs() const { return reduced_; }  // per edge
  // Per edge, the sum over the clique rows holding it of -dual (>= 0): the Lagrangian multipliers
  // of the cliques at this optimum, priced into the edge.
  std::vector<double> edge_prices() const;

  // solve(), then up to `rounds` times: add the violated clique rows of `exclusion` (cliques.h)
  // and odd-set rows, and solve again; stops early when none is violated. Rows of the pool
  // (drop_slack_rows()) that the solution violates come back first, however many rounds that
  // takes: an optimum returned satisfies every row the relaxation ever had, so an integral one
  // is a matching without conflicts.
  LpStatus solve_with_cuts(const Adjacency& exclusion, double cutoff, double seconds, int rounds);

  // Moves the clique and odd-set rows that are slack at the current optimum into the pool: the
  // LP the search re-solves at every node shrinks to the rows that bind, each node's dual simplex
  // gets that much cheaper, and a pooled row is added back when a node's solution violates it.
  // Call between solves, before any basis() is kept.
  void drop_slack_rows();

  // Gomory mixed-integer cuts (Gomory 1960) of the current optimal basis, at most `max_cuts`,
  // made by GLPK's glp_gmi_gen() and added as rows (dense ones; drop_slack_rows() deletes those
  // that go slack instead of pooling them). Valid for every 0/1 point of the current rows and
  // bounds: call at the root only. Returns how many.
  std::size_t add_gomory_cuts(int max_cuts);

  // The degree, clique and odd-set rows of the LP with their duals at the last solve, for
  // check_dual_bound() (dual_bound.h). Gomory rows are left out, since the problem alone cannot
  // show them valid: the bound of the others is weaker then, still valid.
  std::vector<DualRow> dual_rows() const;

  LpBasis basis() const;
  void restore(const LpBasis& basis);

 private:
  // Adds rows sum_{e in C} x_e <= 1 (cliques of the exclusion graph, e.g. separated ones).
  void add_cliques(const std::vector<Clique>& cliques);

  // Odd sets S of ports (no virtual port) spanned by a component of the fractional edges whose
  // row x(E(S)) <= (|S| - 1) / 2 the current solution violates; adds their rows. Returns how many.
  std::size_t add_violated_odd_sets();

  // Solves once, without the pool; stops early with `cutoff` once the bound provably exceeds it.
  LpStatus solve(double cutoff, double seconds);
  void read_solution();

  struct Deleter {
    void operator()(glp_prob* p) const;
  };
  // A row sum_{e in edges} x_e <= bound out of the LP.
  struct PooledRow {
    std::vector<std::uint32_t> edges;
    double bound = 1.0;
    bool clique = true;
  };
  // Per GLPK row (1-based), 1 if it is a clique row.
  std::vector<std::uint8_t> clique_row_marks() const;
  // The edges of GLPK row `row`, increasing.
  std::vector<std::uint32_t> row_edges(int row) const;
  // Adds the pooled rows the current solution violates, takes them out of the pool; how many.
  std::size_t add_violated_pooled_rows();
  void add_clique_row(const Clique& clique);

  const MatchingProblem& problem_;
  std::unique_ptr<glp_prob, Deleter> lp_;
  std::vector<std::pair<int, Clique>> clique_rows_;  // GLPK row (1-based) and its clique
  std::vector<PooledRow> pool_;
  double objective_ = 0.0;
  std::vector<double> values_, reduced_;
};

}  // namespace tessera::matching
