#include "matching/branch_and_bound.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

namespace tessera::matching {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kIntegral = 1e-6;
constexpr int kNodeCutRounds = 2;
constexpr double kPreferredWeight = 2.0;  // branching_edge()
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Fix {
  std::uint32_t edge = 0;
  std::int8_t value = 0;
};

// The branching that made a node: its parent's bound and the branched edge's value there.
struct Branch {
  std::int64_t edge = -1;  // -1 at the root
  std::int8_t value = 0;
  double parent_bound = 0.0;
  double parent_value = 0.0;
};

struct Node {
  std::vector<Fix> fixes;  // on top of the root's bounds
  double bound = -kInfinity;
  LpBasis basis;
  std::uint64_t order = 0;
  Branch branch;
};

// Pseudocosts: per edge and direction, the mean bound gain per unit of change of x_e seen when
// branching on it. An edge not branched on yet counts with the mean over all edges.
class Pseudocosts {
 public:
  explicit Pseudocosts(std::size_t edges) : sum_(edges, {0.0, 0.0}), count_(edges, {0, 0}) {}

  void record(const Branch& branch, double bound) {
    if (branch.edge < 0) return;
    const double change = branch.value ? 1.0 - branch.parent_value : branch.parent_value;
    if (!(change > 0) || !std::isfinite(bound)) return;
    const double gain = std::max(0.0, bound - branch.parent_bound) / change;
    const int d = branch.value;
    sum_[branch.edge][d] += gain;
    ++count_[branch.edge][d];
    total_[d] += gain;
    ++total_count_[d];
  }

  // The product score of branching on e at value x (larger is better).
  double score(std::uint32_t e, double x) const {
    const double down = mean(e, 0) * x, up = mean(e, 1) * (1.0 - x);
    return std::max(down, kMinGain) * std::max(up, kMinGain);
  }

 private:
  static constexpr double kMinGain = 1e-6;
  double mean(std::uint32_t e, int d) const {
    if (count_[e][d] > 0) return sum_[e][d] / count_[e][d];
    return total_count_[d] > 0 ? total_[d] / total_count_[d] : 1.0;
  }
  std::vector<std::array<double, 2>> sum_;
  std::vector<std::array<std::uint32_t, 2>> count_;
  std::array<double, 2> total_{0.0, 0.0};
  std::array<std::uint32_t, 2> total_count_{0, 0};
};

struct LeastBound {
  bool operator()(const Node& a, const Node& b) const {
    if (a.bound != b.bound) return a.bound > b.bound;
    return a.order > b.order;
  }
};

class Search {
 public:
  Search(const MatchingProblem& problem, LpRelaxation& lp, const Adjacency& exclusion,
         const std::vector<Fixed>& root, const std::vector<std::uint8_t>& preferred,
         const IncumbentSearch& heuristics, Incumbent start, double root_bound,
         const SearchLimits& limits, const Progress& progress)
      : problem_(problem),
        lp_(lp),
        exclusion_(exclusion),
        preferred_(preferred),
        heuristics_(heuristics),
        best_(std::move(start)),
        root_bound_(root_bound),
        limits_(limits),
        progress_(progress),
        root_(root.size()),
        pseudocosts_(root.size()) {
    for (std::size_t e = 0; e < root.size(); ++e) root_[e] = static_cast<std::int8_t>(root[e]);
    current_ = root_;
  }

  SearchResult run() {
    Node root;
    root.bound = root_bound_;
    open_.push(std::move(root));
    double stopped_bound = kInfinity;
    while (!open_.empty()) {
      Node node = open_.top();
      open_.pop();
      if (node.bound >= cutoff()) continue;
      if (Clock::now() >= limits_.deadline || nodes_ >= limits_.max_nodes) {
        stopped_bound = node.bound;
        break;
      }
      if (!dive(std::move(node), stopped_bound)) break;
    }
    SearchResult result;
    result.complete = open_.empty() && stopped_bound == kInfinity;
    double bound = stopped_bound;
    while (!open_.empty()) {
      bound = std::min(bound, open_.top().bound);
      open_.pop();
    }
    result.lower_bound = best_.found ? std::min(bound, best_.objective) : bound;
    result.best = std::move(best_);
    result.nodes = nodes_;
    return result;
  }

 private:
  double cutoff() const {
    return best_.found ? best_.objective - bound_tolerance(best_.objective) : kInfinity;
  }

  void set(std::uint32_t e, int value) {
    if (current_[e] == value) return;
    current_[e] = static_cast<std::int8_t>(value);
    if (value < 0) {
      lp_.set_bounds(e, 0, 1);
    } else {
      lp_.set_bounds(e, value, value);
    }
  }

  void apply(const Node& node) {
    std::vector<std::int8_t> target = root_;
    for (const Fix& f : node.fixes) target[f.edge] = f.value;
    for (std::uint32_t e = 0; e < current_.size(); ++e) set(e, target[e]);
    if (!node.basis.columns.empty()) lp_.restore(node.basis);
  }

  // Reduced-cost fixing: edges whose reduced cost lifts the bound past the incumbent.
  void fix_by_reduced_cost(Node& node) {
    if (!best_.found) return;
    const double slack = cutoff() - lp_.objective();
    const std::vector<double>& x = lp_.values();
    const std::vector<double>& d = lp_.reduced_costs();
    for (std::uint32_t e = 0; e < current_.size(); ++e) {
      if (current_[e] >= 0) continue;
      const int value = x[e] < kIntegral && d[e] >= slack          ? 0
                        : x[e] > 1.0 - kIntegral && -d[e] >= slack ? 1
                                                                   : -1;
      if (value < 0) continue;
      set(e, value);
      node.fixes.push_back({e, static_cast<std::int8_t>(value)});
    }
  }

  // The fractional edge to branch on: the best pseudocost score, counted kPreferredWeight times
  // for a preferred edge, the lowest index on ties.
  std::int64_t branching_edge() const {
    const std::vector<double>& x = lp_.values();
    std::int64_t best = -1;
    double best_score = -1.0;
    for (std::uint32_t e = 0; e < x.size(); ++e) {
      if (x[e] < kIntegral || x[e] > 1.0 - kIntegral) continue;
      double score = pseudocosts_.score(e, x[e]);
      if (!preferred_.empty() && preferred_[e]) score *= kPreferredWeight;
      if (score > best_score) {
        best = e;
        best_score = score;
      }
    }
    return best;
  }

  void take_integral_solution() {
    Incumbent found;
    found.found = true;
    for (std::uint32_t e = 0; e < current_.size(); ++e)
      if (lp_.values()[e] > 0.5) found.edges.push_back(e);
    found.objective = objective_of(problem_, found.edges);
    heuristics_.improve(found);
    if (!best_.found || found.objective < best_.objective) best_ = std::move(found);
  }

  void report() {
    const double now = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
    if (now - last_report_ < 0.1) return;
    last_report_ = now;
    const double bound = open_.empty() ? kInfinity : open_.top().bound;
    const double gap =
        best_.found && std::isfinite(bound)
            ? std::max(0.0, best_.objective - bound) / std::max(std::abs(best_.objective), 1e-9)
            : 1.0;
    progress_.step("exact", std::clamp(1.0 - gap, 0.0, 1.0));
  }

  // Explores `node` depth-first along x_e = 1 branches, leaving the x_e = 0 siblings open. False
  // when the deadline stopped it; `stopped_bound` then holds the bound of the unfinished node.
  bool dive(Node node, double& stopped_bound) {
    apply(node);
    for (;;) {
      ++nodes_;
      report();
      const double seconds = std::chrono::duration<double>(limits_.deadline - Clock::now()).count();
      const LpStatus status = lp_.solve_with_cuts(exclusion_, cutoff(), seconds, kNodeCutRounds);
      if (status == LpStatus::time_limit) {
        stopped_bound = node.bound;
        return false;
      }
      if (status != LpStatus::optimal) {
        // A child cut off or infeasible lifted the bound at least to the incumbent.
        pseudocosts_.record(node.branch, cutoff());
        return true;
      }
      pseudocosts_.record(node.branch, lp_.objective());
      node.bound = std::max(node.bound, lp_.objective());
      // The simplex's cutoff stops only on a bound strictly above it: a fractional optimum as
      // dear as the incumbent ends here too, or its degenerate subtree is searched in vain.
      if (node.bound >= cutoff()) return true;
      fix_by_reduced_cost(node);
      const std::int64_t e = branching_edge();
      if (e < 0) {
        take_integral_solution();
        return true;
      }
      const double value = lp_.values()[e];
      Node sibling{node.fixes, node.bound, lp_.basis(), ++created_, {e, 0, node.bound, value}};
      sibling.fixes.push_back({static_cast<std::uint32_t>(e), 0});
      open_.push(std::move(sibling));
      node.branch = {e, 1, node.bound, value};
      node.fixes.push_back({static_cast<std::uint32_t>(e), 1});
      set(static_cast<std::uint32_t>(e), 1);
    }
  }

  const MatchingProblem& problem_;
  LpRelaxation& lp_;
  const Adjacency& exclusion_;
  const std::vector<std::uint8_t>& preferred_;
  const IncumbentSearch& heuristics_;
  Incumbent best_;
  double root_bound_;
  SearchLimits limits_;
  const Progress& progress_;
  std::vector<std::int8_t> root_;     // per edge: -1 free, else the value preprocessing fixed
  std::vector<std::int8_t> current_;  // per edge: -1 free, else the value it is fixed to now
  std::priority_queue<Node, std::vector<Node>, LeastBound> open_;
  Pseudocosts pseudocosts_;
  std::uint64_t nodes_ = 0, created_ = 0;
  double last_report_ = 0.0;
};

}  // namespace

double bound_tolerance(double incumbent) {
  return 1e-9 * std::max(1.0, std::abs(incumbent));
}

SearchResult branch_and_bound(const MatchingProblem& problem, LpRelaxation& lp,
                              const Adjacency& exclusion, const std::vector<Fixed>& root,
                              const std::vector<std::uint8_t>& preferred,
                              const IncumbentSearch& heuristics, Incumbent start, double root_bound,
                              const SearchLimits& limits, const Progress& progress) {
  return Search(problem, lp, exclusion, root, preferred, heuristics, std::move(start), root_bound,
                limits, progress)
      .run();
}

}  // namespace tessera::matching
