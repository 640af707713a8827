// The machine-readable form of a quad layout: one definition shared by `tessera layout --json`, the
// GLB's extras and the wasm module. Keys of issue 4: singularities (|S|), graph_edges (|E_G|),
// conflicts (|I|), patches (|P|), angle_rsd (percent), valid (the project's checker), objective
// (of P1), seconds (per stage); and alpha, ports, virtual_ports, nodes, arcs, solver,
// matching_status, lower_bound, curved_edges, twin_edges, loop_conflicts,
// length_limit, length_doublings, unmatchable_ports, folded_singularities (vertices),
// average_separatrix_length, problems (the first few), problem_count.
#pragma once

#include <nlohmann/json.hpp>

#include "layout/quad_layout.h"

namespace tessera::layout {

nlohmann::ordered_json layout_json(const LayoutGraph& graph, const QuadLayout& layout);

}  // namespace tessera::layout
