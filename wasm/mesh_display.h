// What the viewer draws of a mesh: positions as Float32Array (3V), polygons fanned into triangles
// from their first corner as Uint32Array (3T), and the face of each triangle as Uint32Array (T).
#pragma once

#include <emscripten/val.h>

#include "mesh/mesh.h"

namespace tessera::wasm {

// Sets positions, triangles and triangleFace on `result`.
void set_display_arrays(emscripten::val& result, const Mesh& mesh);

}  // namespace tessera::wasm
