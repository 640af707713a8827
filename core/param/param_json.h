// The machine-readable form of a cross field's singularities and of a seamless parameterization:
// one definition shared by `tessera field|param --json` and the wasm module.
#pragma once

#include <nlohmann/json.hpp>

#include "field/cross_field.h"
#include "param/seamless_param.h"

namespace tessera {

// {"euler_characteristic", "index_sum", "singularities": [{"vertex", "index", "valence"}]}.
nlohmann::ordered_json singularities_json(const CrossField& field);

// singularities_json() plus flipped_triangles, flipped_outside_singular_rings,
// flipped_before_injectivity, max_seam_error, energy, h, seconds (per step).
nlohmann::ordered_json param_json(const CrossField& field, const SeamlessParam& param);

}  // namespace tessera
