#include "export/byte_writer.h"
#include "export/writers.h"

namespace tessera {

std::vector<std::uint8_t> write_off(const Mesh& mesh) {
  ByteWriter out;
  out.text("OFF\n");
  out.integer(static_cast<long long>(mesh.vertex_count()));
  out.text(" ");
  out.integer(static_cast<long long>(mesh.face_count()));
  out.text(" 0\n");
  for (const Eigen::Vector3d& p : mesh.positions) {
    for (int i = 0; i < 3; ++i) {
      if (i) out.text(" ");
      out.number(p[i]);
    }
    out.text("\n");
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    out.integer(static_cast<long long>(mesh.face_size(f)));
    for (Index v : mesh.face(f)) {
      out.text(" ");
      out.integer(v);
    }
    out.text("\n");
  }
  return out.take();
}

}  // namespace tessera
