// Resource limits, in one place. Every limit has a CLI flag that raises it; a hit throws LimitError
// naming the limit and the flag. Defaults fit a browser tab (the wasm module's memory cap).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace tessera {

struct Limits {
  std::size_t max_vertices = 4'000'000;        // --max-vertices
  std::size_t max_faces = 8'000'000;           // --max-faces
  std::size_t max_file_bytes = 1'500'000'000;  // --max-file-bytes
  std::size_t max_coset_table = 4'000'000;     // --max-cosets (rows of a coset table)
  double max_coset_seconds = 20.0;             // --max-seconds (coset enumeration)
  std::size_t max_tiling_triangles = 250'000;  // --max-triangles (Tri(G) of a regular map)
  std::size_t max_trace_steps = 20'000'000;    // --max-trace-steps (faces crossed by all
                                               //   separatrices of a quad layout)
  double max_trace_seconds = 60.0;             // --max-trace-seconds (growing them)
  double max_solve_seconds = 60.0;             // --max-solve-seconds (program P1 of a layout)
  std::size_t max_matching_nodes = 1'000'000;       // --max-nodes (ports of a P1 instance)
  std::size_t max_matching_edges = 4'000'000;       // --max-edges (edges of a P1 instance)
  std::size_t max_matching_conflicts = 40'000'000;  // --max-conflicts (conflict pairs of P1)
};

// "10 s", "0.5 s": a time limit as people write it.
std::string format_seconds(double seconds);

// Throws LimitError("<what> has <value>, above the limit <limit> (<flag>) ...") if value > limit.
// 64-bit on every target, so that a count announced by a file is not truncated in wasm32 first.
void check_limit(std::uint64_t value, std::uint64_t limit, const std::string& what,
                 const std::string& flag);

}  // namespace tessera
