// The machine-readable form of a quad-mesh optimization (issue 40), shared by
// `tessera optimize-quads --json` and the wasm module: singularities, base_complex_patches (B),
// patches (after P1), angle_rsd (percent, parameter space), graph_edges (|E_G|), conflicts (|I|,
// with Z), matching_status, seconds (per stage); and quads, valid (the checker on the layout over
// the quad mesh), base_complex_valid, objective, lower_bound, alpha, diagonals, ports,
// virtual_ports, separatrix_edges, crossing_edges, diagonal_edges, zero_area_pairs,
// rejected_by_window, curved_edges, twin_edges, cut_quads, rounds, problems, problem_count.
#pragma once

#include <nlohmann/json.hpp>

#include "quadmesh/optimize_quads.h"

namespace tessera::quadmesh {

nlohmann::ordered_json quad_layout_json(const QuadGraph& graph, const QuadLayoutResult& result,
                                        bool diagonals);

}  // namespace tessera::quadmesh
