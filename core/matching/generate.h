// Generated P1 instances, for tests and benchmarks while no layout stage produces real ones.
// Deterministic: the same spec (seed included) gives the same instance on every platform.
#pragma once

#include <cstdint>

#include "matching/problem.h"

namespace tessera::matching {

// A random multigraph with a planted matching that covers every port.
struct PlantedSpec {
  std::uint32_t ports = 30;  // with no virtual ports, an odd count makes it infeasible
  std::uint32_t virtual_ports = 0;
  std::uint32_t extra_edges = 60;     // random edges besides the planted matching
  std::uint32_t conflicts = 60;       // random conflict pairs
  bool keep_planted_feasible = true;  // no conflict pairs two planted edges
  // Disjoint 4-cycles of fresh ports whose two perfect matchings both hold a conflict pair: G keeps
  // a perfect matching but P1 becomes infeasible.
  std::uint32_t blocked_squares = 0;
  double max_weight = 10.0;  // weights uniform in [1, max_weight]
  std::uint64_t seed = 1;
};

MatchingProblem planted_instance(const PlantedSpec& spec);

// An instance shaped like the thesis' P1 graphs (Sec. 4.2-4.6, Appendix B): singularities on a flat
// torus, each port an axis direction; an edge joins a port to an opposite port ahead of it within
// 45 degrees (condition C1), kept by the window reduction of Prop. 4.1 per side, with weight
// base + alpha * height; two edges of the same alignment whose arcs cross form a conflict pair
// (illegal crossing, Sec. 4.6). Synthetic: the geometry is random, not traced on a surface.
struct SyntheticLayoutSpec {
  std::uint32_t singularity_pairs = 60;  // a valence-3 and a valence-5 singularity each (8 ports)
  double alpha = 5.0;                    // the weight's height factor (thesis default 5)
  double max_length = 10.0;              // L_max, in mean distances between singularities
  // Each weight is scaled by a random factor in [1 - noise, 1 + noise]. On a curved surface the
  // lengths of separatrices obey no triangle inequality of the plane; without noise, swapping the
  // ends of two crossing edges would always be cheaper and conflicts would never bind.
  double weight_noise = 0.3;
  // The share of crossings of an x- and a y-aligned edge that are illegal all the same (Remark 4.1,
  // self-crossing lines). Without them the x- and y-aligned halves would be independent problems,
  // which real port graphs are not: chart rotations around singularities mix the two.
  double mixed_crossing_rate = 0.05;
  std::uint64_t seed = 1;
};

MatchingProblem synthetic_layout_instance(const SyntheticLayoutSpec& spec);

}  // namespace tessera::matching
