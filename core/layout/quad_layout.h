// The quad layout of a triangle mesh with a seamless parameterization (thesis Ch. 4-6), in two
// steps so that a change of alpha reruns only the second (SPEC "Data flow"):
//  1. build_layout_graph(): ports, motorcycle growing to L_max = length_factor * diameter / h
//     (Sec. 6.9, the diameter taken as the bounding-box diagonal), the edges whose hypotenuse is
//     straight, and, if G has no perfect matching, growing on with L_max doubled (Sec. 5.1); one
//     edge kept of each pair of twins (twin_edges.h); then the conflicts I (Sec. 4.6);
//  2. solve_layout(): program P1 with w = L_base + alpha L_height (Ch. 5) by a solver of
//     core/matching,
//     the chosen edges traced as arcs, the mesh refined along them, patches, the validity check,
//     the angle RSD; while the check finds patches that are no disks, P1 again with the chosen
//     pairs that close loops around a handle as conflicts (conflicts.h, loop_pairs()); all
//     solves of P1 together within limits.max_solve_nodes branch-and-bound nodes (work: the
//     same layout on every run) and the time guard limits.max_solve_seconds (a layout it stopped
//     says so: matching.stopped_by).
//
// In:  the charts of M_f (charts.h), options. Out: plain values; the refined mesh carries the face
//      attribute "patch". Throws LimitError (tracing steps, crossings or the time guard),
//      CancelledError.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/limits.h"
#include "base/progress.h"
#include "layout/arcs.h"
#include "layout/layout_check.h"
#include "layout/port_graph.h"
#include "layout/refine.h"
#include "matching/result.h"
#include "matching/solver.h"

namespace tessera::layout {

struct LayoutOptions {
  double rho = 10;               // spiral test (6.7), (6.8)
  double length_factor = 3;      // L_max = length_factor * diameter / h, in parameter units
  int max_length_doublings = 3;  // Sec. 5.1: while G has no perfect matching
  Limits limits;                 // max_trace_*, max_solve_* (counts, and time guards)
};

struct StageSeconds {
  std::string stage;
  double seconds = 0;
};

struct QuadLayout;

// The conflict pairs that a round whose layout failed the check adds to P1 for the next round.
using RepairPairs = std::vector<EdgePair> (*)(const Charts& charts, const PortGraph& graph,
                                              const QuadLayout& failed);

struct LayoutGraph {
  PortGraph graph;
  std::vector<Arc> arcs;         // of every edge, in edge order
  std::size_t curved_edges = 0;  // candidates dropped: their hypotenuse is not straight
  std::size_t twin_edges = 0;    // removed as twins of kept edges (twin_edges.h)
  int length_doublings = 0;      // of L_max, until G had a perfect matching
  std::vector<std::uint32_t> unmatchable_ports;  // no matching of G covers them (empty: fine)
  std::size_t trace_steps = 0;      // faces crossed by all separatrices (Limits::max_trace_steps)
  std::size_t trace_crossings = 0;  // crossings they found (Limits::max_trace_crossings)
  std::vector<StageSeconds> seconds;
  // Null: loop_pairs() of the failed round's arcs (conflicts.h). A graph with more known about
  // it sets its own (the supergraph of a quad mesh, Ch. 7).
  RepairPairs repair_pairs = nullptr;
};

struct QuadLayout {
  double alpha = 0;
  matching::SolverKind solver = matching::SolverKind::exact;
  matching::MatchingResult matching;
  std::vector<Arc> arcs;
  RefinedMesh refined;  // refined.mesh.face_attributes["patch"]
  LayoutCheck check;
  double angle_rsd = 0;  // percent, over all patch corners (parameter space)
  // Pairs of chosen arcs closing loops (conflicts.h, loop_pairs()) that each failed round added to
  // P1, in the order of the rounds: round k + 2 solved P1 with loop_rounds[0..k] added.
  std::vector<std::vector<EdgePair>> loop_rounds;
  // Solves of P1 that led to this layout: the first and its loop rounds.
  int rounds() const { return static_cast<int>(loop_rounds.size()) + 1; }
  // Rounds whose matching had been laid out before (ResolveCache): no arcs, refinement or check.
  int reused_rounds = 0;
  // The rounds of P1 were run at this alpha before (ResolveCache::solved): none ran now.
  bool solved_before = false;
  // Branch-and-bound nodes of the rounds that ran now (Limits::max_solve_nodes).
  std::uint64_t p1_nodes = 0;
  std::vector<StageSeconds> seconds;
};

// What solve_layout() found at one alpha: the matching it returned and the rounds it took.
struct SolvedAlpha {
  matching::MatchingResult matching;
  std::vector<std::vector<EdgePair>> loop_rounds;
};

// What solve_layout() keeps from one alpha to the next of one graph (SPEC "Data flow"); pass the
// same one for every alpha of a graph and a new one for another graph. The results are the same
// with it or without it.
//  - p1: the exact solver's weight-free preprocessing (matching/exact_solver.h);
//  - what the layout stages found for matchings laid out before. Arcs, refinement and check read
//    the chosen edges, not alpha, and neighbouring alphas often share an optimum (the weights
//    are linear in alpha): of the 60 rounds of fertility's 41 slider positions, 0 to 20, 29
//    chose a matching laid out before, among them the first round of alpha 5.5 to 9 (alpha 5's,
//    whose patches are no disks) and the one round of alpha 10 to 11 (alpha 9.5's layout);
//  - the matching found at every alpha solved before with a proven optimum: solving there again
//    only lays it out. presolve_layout() fills it ahead of the slider (the page's worker, when
//    idle), so that a move to a presolved alpha costs one layout and no P1.
struct ResolveCache {
  matching::ExactSolverCache p1;
  // Per matching (its edges, increasing) whose layout failed the check: its loop pairs.
  std::map<std::vector<std::uint32_t>, std::vector<EdgePair>> failed;
  std::map<std::pair<matching::SolverKind, double>, SolvedAlpha> solved;  // by solver and alpha
  std::optional<QuadLayout> last;  // the layout solve_layout() returned last
};

LayoutGraph build_layout_graph(const Charts& charts, const LayoutOptions& options,
                               const Progress& progress);

// `cache` may be null: the rounds of this call then share their own.
QuadLayout solve_layout(const Charts& charts, const LayoutGraph& graph, double alpha,
                        matching::SolverKind solver, const Limits& limits, const Progress& progress,
                        ResolveCache* cache = nullptr);

// The rounds of solve_layout() at `alpha` into `cache.solved`, unless they are there; keeps
// `cache.last`. Returns whether the alpha is solved now (false: no proven optimum in the limits).
bool presolve_layout(const Charts& charts, const LayoutGraph& graph, double alpha,
                     matching::SolverKind solver, const Limits& limits, const Progress& progress,
                     ResolveCache& cache);

// The mean length of the separatrices as grown (Table 6.1).
double average_separatrix_length(const PortGraph& graph);

}  // namespace tessera::layout
