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
  // A layout's work is bounded by counts, so that its result is a function of the input and the
  // options, whatever the machine and its load. The seconds are a last-resort guard above what
  // the counts allow on a loaded machine; a result stopped by one says so. The shared dragon
  // (25k triangles) crosses 1.4 M faces and finds 7.5 M crossings, in 76 s on an idle 2-core
  // machine and 224 s with both cores busy with other work: 20 M crossings would take about
  // 200 s and 600 s.
  std::size_t max_trace_steps = 20'000'000;      // --max-trace-steps (faces crossed by all
                                                 //   separatrices of a quad layout)
  std::size_t max_trace_crossings = 20'000'000;  // --max-trace-crossings (their crossings found)
  double max_trace_seconds = 1800.0;             // --max-trace-seconds (time guard: growing them)
  std::uint64_t max_solve_nodes = 5'000;         // --max-solve-nodes (branch-and-bound nodes of all
                                                 //   solves of program P1 of a layout)
  double max_solve_seconds = 1800.0;             // --max-solve-seconds (time guard: those solves)
  std::size_t max_matching_nodes = 1'000'000;    // --max-nodes (ports of a P1 instance)
  std::size_t max_matching_edges = 4'000'000;    // --max-edges (edges of a P1 instance)
  std::size_t max_matching_conflicts = 40'000'000;  // --max-conflicts (conflict pairs of P1)
};

// "10 s", "0.5 s": a time limit as people write it.
std::string format_seconds(double seconds);

// Throws LimitError("<what> has <value>, above the limit <limit> (<flag>) ...") if value > limit.
// 64-bit on every target, so that a count announced by a file is not truncated in wasm32 first.
void check_limit(std::uint64_t value, std::uint64_t limit, const std::string& what,
                 const std::string& flag);

}  // namespace tessera
