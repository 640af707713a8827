// STL: a soup of triangles, binary (80-byte header, uint32 count, 50 bytes per triangle) or ascii
// ("facet normal ... outer loop vertex x y z x3 endloop endfacet"). Vertices are welded where their
// coordinates are bit-identical, which is how STL writers repeat a shared vertex.
#include <cctype>
#include <cstring>
#include <string_view>

#include "base/error.h"
#include "base/text_scan.h"
#include "mesh/byte_reader.h"
#include "mesh/exact_welder.h"
#include "mesh/readers.h"

namespace tessera {
namespace {

constexpr std::size_t kBinaryHeaderBytes = 84;
constexpr std::size_t kBinaryTriangleBytes = 50;

bool starts_with_solid(Bytes bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && std::isspace(bytes[i])) ++i;
  return bytes.size() - i >= 5 && std::memcmp(bytes.data() + i, "solid", 5) == 0;
}

Mesh read_binary_stl(Bytes bytes, const std::string& file_name, const Limits& limits) {
  ByteReader reader(bytes, 0, false, file_name);
  reader.skip(80, "the 80-byte header");
  const std::uint32_t count = reader.read<std::uint32_t>("the triangle count");
  check_limit(count, limits.max_faces, "the triangle list of " + file_name, "--max-faces");
  const std::uint64_t needed = std::uint64_t{count} * kBinaryTriangleBytes;
  if (needed > reader.remaining())
    reader.fail("the header announces " + std::to_string(count) + " triangles (" +
                std::to_string(needed) + " bytes) but only " + std::to_string(reader.remaining()) +
                " bytes follow; the file is truncated");
  Mesh mesh;
  mesh.face_offsets.reserve(count + 1);
  ExactWelder welder(mesh);
  for (std::uint32_t t = 0; t < count; ++t) {
    reader.skip(12, "a facet normal");
    Index corners[3];
    for (Index& corner : corners) {
      Eigen::Vector3d p;
      for (int i = 0; i < 3; ++i) p[i] = reader.read<float>("a vertex");
      if (!p.allFinite())
        throw_non_finite_position(mesh.vertex_count(), file_name + ": byte " +
                                                           std::to_string(reader.offset() - 12) +
                                                           " (triangle " + std::to_string(t) + ")");
      corner = welder.vertex(p);
    }
    reader.skip(2, "the attribute byte count");
    mesh.add_face(corners);
  }
  if (mesh.vertex_count() > limits.max_vertices)
    check_limit(mesh.vertex_count(), limits.max_vertices, "the vertex list of " + file_name,
                "--max-vertices");
  return mesh;
}

Mesh read_ascii_stl(Bytes bytes, const std::string& file_name, const Limits& limits) {
  TextLines lines(bytes, file_name);
  Mesh mesh;
  ExactWelder welder(mesh);
  std::vector<Index> corners;
  bool in_facet = false;
  std::string_view line;
  while (lines.next(line)) {
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    if (keyword == "facet") {
      if (in_facet) lines.fail("\"facet\" inside a facet; the previous one lacks \"endfacet\"");
      in_facet = true;
      corners.clear();
    } else if (keyword == "vertex") {
      if (!in_facet) lines.fail("\"vertex\" outside a facet");
      Eigen::Vector3d p;
      for (int i = 0; i < 3; ++i) {
        std::string_view token;
        const auto value = tokens.next(token) ? parse_double(token) : std::nullopt;
        if (!value) lines.fail("a vertex needs three numbers \"vertex x y z\"");
        p[i] = *value;
      }
      if (!p.allFinite())
        throw_non_finite_position(mesh.vertex_count(),
                                  file_name + ":" + std::to_string(lines.line_number()));
      if (mesh.vertex_count() == limits.max_vertices)
        check_limit(mesh.vertex_count() + 1, limits.max_vertices, "the vertex list of " + file_name,
                    "--max-vertices");
      corners.push_back(welder.vertex(p));
    } else if (keyword == "endfacet") {
      if (!in_facet) lines.fail("\"endfacet\" without \"facet\"");
      if (corners.size() != 3)
        lines.fail("a facet needs exactly 3 vertices, this one has " +
                   std::to_string(corners.size()));
      if (mesh.face_count() == limits.max_faces)
        check_limit(mesh.face_count() + 1, limits.max_faces, "the triangle list of " + file_name,
                    "--max-faces");
      mesh.add_face(corners);
      in_facet = false;
    }
    // solid, endsolid, outer loop, endloop and the facet normal carry nothing Tessera uses.
  }
  if (in_facet) lines.fail("the file ends inside a facet; it is truncated");
  return mesh;
}

}  // namespace

Mesh read_stl(Bytes bytes, const std::string& file_name, const Limits& limits) {
  // Binary files may start with "solid" too; a size that matches the triangle count settles it.
  if (bytes.size() >= kBinaryHeaderBytes) {
    const std::uint32_t count =
        ByteReader(bytes, 80, false, file_name).read<std::uint32_t>("the triangle count");
    if (bytes.size() == kBinaryHeaderBytes + std::uint64_t{count} * kBinaryTriangleBytes)
      return read_binary_stl(bytes, file_name, limits);
  }
  if (starts_with_solid(bytes)) return read_ascii_stl(bytes, file_name, limits);
  if (bytes.size() < kBinaryHeaderBytes)
    throw ParseError(file_name + ": " + std::to_string(bytes.size()) +
                     " bytes are neither ascii STL (no \"solid\") nor binary STL (84 bytes at "
                     "least); the file is truncated or not STL");
  return read_binary_stl(bytes, file_name, limits);
}

}  // namespace tessera
