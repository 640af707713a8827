// Figures of a quad layout (thesis Sec. 6.9, Table 6.1, Fig. 6.8): the patch corner angles measured
// in parameter space and their relative standard deviation.
//
// The angle of patch p at its corner v is the sum of the parameter-space angles at v of p's faces
// of the refined mesh (each face's corners carry (u, v) in its parent face's chart; charts differ
// by rigid motions, so angles agree). Arcs are straight in every chart, so this is the angle
// between the two arcs bounding p at v.
#pragma once

#include <cstdint>
#include <vector>

#include "layout/layout_check.h"
#include "layout/refine.h"

namespace tessera::layout {

// Degrees, for every patch corner found by the checker, patch by patch.
std::vector<double> corner_angles(const RefinedMesh& refined,
                                  const std::vector<std::int32_t>& patch, const LayoutCheck& check);

// Standard deviation over mean, in percent; 0 for fewer than two values.
double relative_standard_deviation(const std::vector<double>& values);

}  // namespace tessera::layout
