#include "mesh_display.h"

#include <cstdint>
#include <vector>

#include "typed_arrays.h"

namespace tessera::wasm {

void set_display_arrays(emscripten::val& result, const Mesh& mesh) {
  std::vector<float> positions;
  positions.reserve(3 * mesh.vertex_count());
  for (const Eigen::Vector3d& p : mesh.positions)
    for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(p[k]));
  std::vector<std::uint32_t> triangles;
  std::vector<std::uint32_t> triangle_face;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      triangles.insert(triangles.end(), {face[0], face[k], face[k + 1]});
      triangle_face.push_back(static_cast<std::uint32_t>(f));
    }
  }
  result.set("positions", to_typed_array(positions));
  result.set("triangles", to_typed_array(triangles));
  result.set("triangleFace", to_typed_array(triangle_face));
}

}  // namespace tessera::wasm
