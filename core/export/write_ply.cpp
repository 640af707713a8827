#include <algorithm>

#include "base/error.h"
#include "export/byte_writer.h"
#include "export/writers.h"

namespace tessera {
namespace {

std::size_t largest_face(const Mesh& mesh) {
  std::size_t largest = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    largest = std::max(largest, mesh.face_size(f));
  return largest;
}

void write_header(ByteWriter& out, const Mesh& mesh, bool binary, bool small_faces) {
  out.text("ply\nformat ");
  out.text(binary ? "binary_little_endian" : "ascii");
  out.text(" 1.0\ncomment written by Tessera\nelement vertex ");
  out.integer(static_cast<long long>(mesh.vertex_count()));
  out.text("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  out.integer(static_cast<long long>(mesh.face_count()));
  out.text(small_faces ? "\nproperty list uchar int vertex_indices\n"
                       : "\nproperty list int int vertex_indices\n");
  for (const auto& [name, values] : mesh.face_attributes) {
    // A name with whitespace would break the header; attribute names come from code, not users.
    if (name.empty() || name.find_first_of(" \t\r\n") != std::string::npos)
      throw Error("face attribute name '" + name + "' cannot be a PLY property name");
    out.text("property int " + name + "\n");
  }
  out.text("end_header\n");
}

}  // namespace

std::vector<std::uint8_t> write_ply(const Mesh& mesh, bool binary) {
  ByteWriter out;
  const bool small_faces = largest_face(mesh) <= 255;
  write_header(out, mesh, binary, small_faces);
  for (const Eigen::Vector3d& p : mesh.positions) {
    for (int i = 0; i < 3; ++i) {
      if (binary) {
        out.put(p[i]);
      } else {
        if (i) out.text(" ");
        out.number(p[i]);
      }
    }
    if (!binary) out.text("\n");
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    if (binary) {
      if (small_faces)
        out.put(static_cast<std::uint8_t>(face.size()));
      else
        out.put(static_cast<std::int32_t>(face.size()));
      for (Index v : face) out.put(static_cast<std::int32_t>(v));
      for (const auto& [name, values] : mesh.face_attributes) out.put(values[f]);
    } else {
      out.integer(static_cast<long long>(face.size()));
      for (Index v : face) {
        out.text(" ");
        out.integer(v);
      }
      for (const auto& [name, values] : mesh.face_attributes) {
        out.text(" ");
        out.integer(values[f]);
      }
      out.text("\n");
    }
  }
  return out.take();
}

}  // namespace tessera
