// The machine-readable figures of a quad mesh from a layout (issue 39 "Output"): one definition
// shared by `tessera remesh --json` and the wasm module. Keys: quads, vertices,
// irregular_vertices, patches, layout_valid, lambda, chains, compressed_sides,
// min_scaled_jacobian, mean_scaled_jacobian, nonpositive_jacobian_quads, nonpositive_corners,
// nonpositive_corners_at_nodes, flipped_quads, max_angle_deviation, mean_angle_deviation
// (degrees), manifold, boundary_edges, euler_characteristic, input_euler_characteristic,
// irregular_off_nodes, hausdorff_relative, seconds (per step, as given).
#pragma once

#include <nlohmann/json.hpp>

#include "remesh/remesh.h"

namespace tessera::remesh {

nlohmann::ordered_json remesh_json(const QuadMesh& quads, long input_euler_characteristic,
                                   double hausdorff_relative,
                                   const nlohmann::ordered_json& seconds);

}  // namespace tessera::remesh
