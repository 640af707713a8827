#include "export/byte_writer.h"
#include "export/writers.h"
#include "mesh/geometry.h"

namespace tessera {

std::vector<std::uint8_t> write_stl(const Mesh& mesh) {
  const Mesh triangles = triangulate(mesh);
  ByteWriter out;
  std::string header = "binary STL written by Tessera";
  header.resize(80, ' ');
  out.text(header);
  out.put(static_cast<std::uint32_t>(triangles.face_count()));
  for (Index f = 0; f < triangles.face_count(); ++f) {
    const Eigen::Vector3d n = face_normal(triangles, f);
    for (int i = 0; i < 3; ++i) out.put(static_cast<float>(n[i]));
    for (Index v : triangles.face(f))
      for (int i = 0; i < 3; ++i) out.put(static_cast<float>(triangles.positions[v][i]));
    out.put(std::uint16_t{0});
  }
  return out.take();
}

}  // namespace tessera
