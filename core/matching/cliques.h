// Clique aggregation of the conflict pairs (5.3). The illegal crossings of Sec. 4.6 come in
// bunches: many edges crossing near the same point conflict pairwise, so that thousands of rows
// x_e + x_f <= 1 say the same as a few hundred rows sum_{e in C} x_e <= 1. The cliques are taken in
// the exclusion graph of the edges (conflict pairs plus pairs of edges sharing a node, since a
// matching holds at most one of those too), which makes each row at least as strong as the pairs
// it replaces.
#pragma once

#include <cstdint>
#include <vector>

#include "matching/adjacency.h"
#include "matching/problem.h"

namespace tessera::matching {

using Clique = std::vector<std::uint32_t>;  // edge indices, increasing

// Cliques of the graph `exclusion` that together hold every pair of the graph `pairs` (a subgraph
// of it): each is grown greedily from an uncovered pair by the common neighbour that covers the
// most uncovered pairs, while one covers any (not to maximality: the separation of violated
// cliques extends them where the relaxation needs it). Deterministic.
std::vector<Clique> clique_cover(const Adjacency& exclusion, const Adjacency& pairs);

// clique_cover() of the conflict pairs in the exclusion graph of the problem (adjacency.h).
std::vector<Clique> conflict_cliques(const MatchingProblem& problem);

// Separation: maximal cliques of `exclusion` with sum_{e in C} x_e > 1 + tolerance, grown greedily
// (largest x first) from each fractional edge; no clique twice.
std::vector<Clique> violated_cliques(const Adjacency& exclusion, const std::vector<double>& x,
                                     double tolerance);

}  // namespace tessera::matching
