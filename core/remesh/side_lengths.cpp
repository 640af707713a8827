#include "remesh/side_lengths.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "base/disjoint_sets.h"
#include "base/error.h"

namespace tessera::remesh {
namespace {

// The optimum of (8.1)-(8.3) for one chain. With only the equalities (8.2) between opposite sides
// the chains share no variable, so the program splits into one problem per chain: minimise
// sum_i (l_i - lambda n)^2 over n in N*. It is a convex parabola in n with its minimum at
// mean(l_i) / lambda, so the integer optimum is the nearest integer, and 1 where that is 0: no
// chain is ever forced to 0.
std::vector<int> chain_segments(const std::vector<double>& length,
                                const std::vector<std::size_t>& chain, std::size_t chain_count,
                                double lambda) {
  std::vector<double> sum(chain_count, 0);
  std::vector<int> sides(chain_count, 0);
  for (std::size_t i = 0; i < length.size(); ++i) {
    sum[chain[i]] += length[i];
    ++sides[chain[i]];
  }
  std::vector<int> segments(chain_count);
  for (std::size_t k = 0; k < chain_count; ++k)
    segments[k] = std::max(1, static_cast<int>(std::lround(sum[k] / sides[k] / lambda)));
  return segments;
}

std::vector<std::array<int, 2>> patch_sizes(const PatchSides& sides,
                                            const std::vector<std::size_t>& chain,
                                            const std::vector<int>& segments) {
  std::vector<std::array<int, 2>> size;
  for (const auto& patch : sides.patches)
    size.push_back({segments[chain[patch[0].side]], segments[chain[patch[1].side]]});
  return size;
}

std::size_t quads_at(const PatchSides& sides, const std::vector<double>& length,
                     const std::vector<std::size_t>& chain, std::size_t chain_count,
                     double lambda) {
  std::size_t quads = 0;
  for (const auto& s :
       patch_sizes(sides, chain, chain_segments(length, chain, chain_count, lambda)))
    quads += std::size_t(s[0]) * s[1];
  return quads;
}

// The quad count falls (in steps) as lambda grows: bisect log lambda for the count closest to the
// target, starting from the continuous estimate sum (side 0 x side 1) / lambda^2 = quads.
double lambda_for_quads(const PatchSides& sides, const std::vector<double>& length,
                        const std::vector<std::size_t>& chain, std::size_t chain_count,
                        std::size_t quads) {
  double area = 0;
  for (const auto& patch : sides.patches)
    area += 0.25 * (length[patch[0].side] + length[patch[2].side]) *
            (length[patch[1].side] + length[patch[3].side]);
  const double estimate = std::sqrt(area / double(quads));
  double low = estimate / 8, high = estimate * 8;  // many quads at low, few at high
  for (int step = 0; step < 60; ++step) {
    const double middle = std::sqrt(low * high);
    (quads_at(sides, length, chain, chain_count, middle) > quads ? low : high) = middle;
  }
  const auto miss = [&](double lambda) {
    const double count = double(quads_at(sides, length, chain, chain_count, lambda));
    return std::abs(count - double(quads));
  };
  return miss(low) < miss(high) ? low : high;
}

double lambda_for(const SizeTarget& target, const PatchSides& sides,
                  const std::vector<double>& length, const std::vector<double>& length_3d,
                  const std::vector<std::size_t>& chain, std::size_t chain_count) {
  if (target.quads > 0) return lambda_for_quads(sides, length, chain, chain_count, target.quads);
  if (target.edge_length > 0) {
    // 3D length per parameter unit, over all sides.
    const double scale = std::accumulate(length_3d.begin(), length_3d.end(), 0.0) /
                         std::accumulate(length.begin(), length.end(), 0.0);
    return target.edge_length / scale;
  }
  if (!(target.lambda > 0) || !std::isfinite(target.lambda))
    throw InputError("remesh: the scale lambda must be a positive number");
  return target.lambda;
}

}  // namespace

std::size_t SideLengths::quad_count() const {
  std::size_t quads = 0;
  for (const auto& s : size) quads += std::size_t(s[0]) * s[1];
  return quads;
}

std::vector<std::size_t> compressed_sides(const SideLengths& lengths, double factor) {
  std::vector<std::size_t> result;
  for (std::size_t i = 0; i < lengths.length.size(); ++i)
    if (lengths.lambda * lengths.segments[lengths.chain[i]] > factor * lengths.length[i])
      result.push_back(i);
  return result;
}

std::vector<std::size_t> side_chains(const PatchSides& sides, std::size_t& chain_count) {
  DisjointSets sets(sides.sides.size());
  for (const auto& patch : sides.patches) {
    sets.join(patch[0].side, patch[2].side);  // (8.2): opposite sides
    sets.join(patch[1].side, patch[3].side);
  }
  std::vector<std::size_t> number(sides.sides.size(), sides.sides.size());
  std::vector<std::size_t> chain(sides.sides.size());
  chain_count = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    std::size_t& n = number[sets.find(i)];
    if (n == sides.sides.size()) n = chain_count++;
    chain[i] = n;
  }
  return chain;
}

SideLengths integer_side_lengths(const PatchSides& sides, std::vector<double> length,
                                 std::vector<double> length_3d, const SizeTarget& target) {
  for (std::size_t i = 0; i < length.size(); ++i)
    if (!(length[i] > 0))
      throw InputError("remesh: side " + std::to_string(i) + " (from vertex " +
                       std::to_string(sides.sides[i].vertices.front()) + " to vertex " +
                       std::to_string(sides.sides[i].vertices.back()) +
                       ") has zero length in parameter space");
  SideLengths result;
  std::size_t chain_count = 0;
  result.chain = side_chains(sides, chain_count);
  result.lambda = lambda_for(target, sides, length, length_3d, result.chain, chain_count);
  result.segments = chain_segments(length, result.chain, chain_count, result.lambda);
  result.size = patch_sizes(sides, result.chain, result.segments);
  result.length = std::move(length);
  result.length_3d = std::move(length_3d);
  return result;
}

}  // namespace tessera::remesh
