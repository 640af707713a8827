#include "export/byte_writer.h"
#include "export/writers.h"

#include <string>

#include "base/error.h"

namespace tessera {

std::vector<std::uint8_t> write_obj(const Mesh& mesh, std::span<const Eigen::Vector2d> corner_uv) {
  if (!corner_uv.empty() && corner_uv.size() != mesh.corner_count())
    throw Error("write_obj: " + std::to_string(corner_uv.size()) + " texture coordinates for " +
                std::to_string(mesh.corner_count()) + " corners");
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
  for (const Eigen::Vector2d& uv : corner_uv) {
    out.text("vt ");
    out.number(uv.x());
    out.text(" ");
    out.number(uv.y());
    out.text("\n");
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    out.text("f");
    for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
      out.text(" ");
      out.integer(static_cast<long long>(mesh.face_vertices[c]) + 1);
      if (corner_uv.empty()) continue;
      out.text("/");
      out.integer(static_cast<long long>(c) + 1);
    }
    out.text("\n");
  }
  return out.take();
}

}  // namespace tessera
