#include "export/byte_writer.h"
#include "export/writers.h"

namespace tessera {

std::vector<std::uint8_t> write_obj(const Mesh& mesh) {
  ByteWriter out;
  out.text("# written by Tessera\n");
  for (const Eigen::Vector3d& p : mesh.positions) {
    out.text("v");
    for (int i = 0; i < 3; ++i) {
      out.text(" ");
      out.number(p[i]);
    }
    out.text("\n");
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    out.text("f");
    for (Index v : mesh.face(f)) {
      out.text(" ");
      out.integer(static_cast<long long>(v) + 1);
    }
    out.text("\n");
  }
  return out.take();
}

}  // namespace tessera
