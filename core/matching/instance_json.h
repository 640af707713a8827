// The compact JSON form of a P1 instance (one place that knows it):
//
//   {"format": "tessera-p1", "version": 1, "nodes": 6, "virtual": [5],
//    "edges": [[0, 1, 2.5], [2, 3, 1], ...],        // [u, v, weight]; edge i is the i-th entry
//    "conflicts": [[0, 4], [1, 2], ...]}             // pairs of edge indices
//
// Nodes are numbered 0..nodes-1; those listed in "virtual" are virtual ports, all others ports.
// Weights are written so that they read back as the same doubles.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "base/limits.h"
#include "matching/problem.h"

namespace tessera::matching {

std::vector<std::uint8_t> write_instance_json(const MatchingProblem& problem);

// Throws ParseError (JSON syntax errors with their line; content errors with the key and index,
// e.g. "edges[12]: expected [u, v, weight]"), LimitError when a size exceeds the limits (checked
// before allocating), InputError from validate_problem(). Never reads past `bytes`.
MatchingProblem read_instance_json(std::span<const std::uint8_t> bytes,
                                   const std::string& file_name, const Limits& limits);

}  // namespace tessera::matching
