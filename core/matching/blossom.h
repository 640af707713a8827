// Edmonds' blossom algorithm (LEMON's MaxMatching and MaxWeightedPerfectMatching) on the graph of
// the ports G, without the conflict pairs: the polynomial core of P1 (thesis Sec. 3.1, 5.1).
//
// A matching that covers every port (virtual ports at most once) is turned into a perfect matching
// problem: the virtual ports are joined pairwise by zero-weight dummy edges, plus one dummy node
// joined to all of them when the node count is odd, so that the virtual ports a matching leaves
// uncovered pair up among themselves.
#pragma once

#include <cstdint>
#include <vector>

#include "matching/problem.h"

namespace tessera::matching {

// In: the problem, one weight per edge, and a mask of the edges that may be used (others are left
// out). Out: the cheapest matching of the allowed edges that covers every port, as increasing edge
// indices, or `exists` false when there is none. Parallel edges: only the cheapest one (lowest
// index on ties) is offered. Weights are rounded to 2^-36 of the largest one.
struct PortCover {
  bool exists = false;
  std::vector<std::uint32_t> edges;
};
PortCover min_weight_port_cover(const MatchingProblem& problem, const std::vector<double>& weights,
                                const std::vector<std::uint8_t>& allowed);

// The ports that some maximum matching of the allowed edges leaves uncovered: the set D of the
// Gallai-Edmonds decomposition, restricted to ports. Empty iff a matching covers every port. When
// it is not, the layout stage has to grow its separatrices around these ports (Sec. 5.1).
std::vector<std::uint32_t> deficient_ports(const MatchingProblem& problem,
                                           const std::vector<std::uint8_t>& allowed);

}  // namespace tessera::matching
