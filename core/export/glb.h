// Binary glTF 2.0 (GLB) of a Scene (scene.h), through tinygltf.
//
// In:  a scene whose mesh validate_mesh() accepted (or any mesh with indices in range), colour
//      arrays of the right sizes.
// Out: the GLB bytes: one buffer, positions as floats relative to the bounding-box centre (the
//      node's translation, so that far-from-origin meshes keep their precision), unit normals,
//      min/max on every POSITION accessor, the scene's extras.
// Throws Error if an array's size does not match the mesh (a programming error, not bad input).
#pragma once

#include <cstdint>
#include <vector>

#include "export/scene.h"

namespace tessera {

std::vector<std::uint8_t> write_glb(const Scene& scene);

}  // namespace tessera
