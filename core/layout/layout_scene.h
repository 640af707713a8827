// The GLB content of a quad layout (SPEC "Interfaces"): the refined mesh coloured by patch with its
// per-face "patch" attribute (written as _PATCH), the arcs as one line set, the singularities as
// point sets by valence, and the layout's figures (layout_json()) as extras.
#pragma once

#include "export/scene.h"
#include "layout/layout_json.h"

namespace tessera::layout {

Scene layout_scene(const Charts& charts, const LayoutGraph& graph, const QuadLayout& layout);

// A colour per patch id, neighbours in id order well apart (golden-ratio hue steps).
Color patch_color(std::int32_t patch);

}  // namespace tessera::layout
