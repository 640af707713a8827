// Wavefront OBJ: the statements Tessera needs are "v x y z [w] [r g b]" and "f a b c ...", where
// each corner is "v", "v/vt", "v//vn" or "v/vt/vn" and a negative v counts back from the latest
// vertex.
#include <string_view>

#include "base/error.h"
#include "base/text_scan.h"
#include "mesh/readers.h"

namespace tessera {
namespace {

Eigen::Vector3d parse_vertex(Tokens& tokens, const TextLines& lines) {
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) {
    std::string_view token;
    if (!tokens.next(token)) lines.fail("a vertex needs three coordinates \"v x y z\"");
    const auto value = parse_double(token);
    if (!value) lines.fail(quoted(token) + " is not a number");
    p[i] = *value;
  }
  return p;
}

// The vertex index of one face corner, 0-based. Positive indices may refer to vertices defined
// further down (checked at the end); negative ones are resolved against the vertices so far.
Index parse_corner(std::string_view token, std::size_t vertices_so_far, const TextLines& lines) {
  const std::string_view index_text = token.substr(0, token.find('/'));
  const auto index = parse_integer(index_text);
  if (!index) lines.fail(quoted(token) + " is not a face corner (v, v/vt, v//vn or v/vt/vn)");
  if (*index == 0) lines.fail("vertex index 0 in a face; OBJ indices start at 1");
  if (*index < 0) {
    const auto available = static_cast<std::int64_t>(vertices_so_far);
    if (*index < -available)
      lines.fail("relative vertex index " + std::to_string(*index) +
                 " points before the first vertex (only " + std::to_string(vertices_so_far) +
                 " vertices precede this face)");
    return static_cast<Index>(available + *index);
  }
  if (*index >= static_cast<std::int64_t>(kNoIndex))
    lines.fail("vertex index " + std::to_string(*index) + " is beyond any mesh Tessera can hold");
  return static_cast<Index>(*index - 1);
}

}  // namespace

Mesh read_obj(Bytes bytes, const std::string& file_name, const Limits& limits) {
  Mesh mesh;
  TextLines lines(bytes, file_name);
  std::size_t highest_index = 0;  // 1-based, 0 if none
  std::size_t highest_index_line = 0;
  std::vector<Index> corners;
  std::string_view line;
  while (lines.next(line)) {
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    if (keyword == "v") {
      if (mesh.vertex_count() == limits.max_vertices)
        check_limit(mesh.vertex_count() + 1, limits.max_vertices, "the vertex list of " + file_name,
                    "--max-vertices");
      const Eigen::Vector3d p = parse_vertex(tokens, lines);
      if (!p.allFinite())
        throw_non_finite_position(mesh.vertex_count(),
                                  file_name + ":" + std::to_string(lines.line_number()));
      mesh.add_vertex(p);
    } else if (keyword == "f") {
      if (mesh.face_count() == limits.max_faces)
        check_limit(mesh.face_count() + 1, limits.max_faces, "the face list of " + file_name,
                    "--max-faces");
      corners.clear();
      std::string_view token;
      while (tokens.next(token)) {
        const Index v = parse_corner(token, mesh.vertex_count(), lines);
        if (v + 1 > highest_index) {
          highest_index = v + 1;
          highest_index_line = lines.line_number();
        }
        corners.push_back(v);
      }
      if (corners.size() < 3)
        lines.fail("a face needs at least three corners, this one has " +
                   std::to_string(corners.size()));
      mesh.add_face(corners);
    }
    // Everything else (vt, vn, l, p, o, g, s, usemtl, mtllib, comments) carries nothing Tessera
    // uses.
  }
  if (highest_index > mesh.vertex_count())
    throw ParseError(file_name + ":" + std::to_string(highest_index_line) + ": vertex index " +
                     std::to_string(highest_index) + " is out of range: the file has only " +
                     std::to_string(mesh.vertex_count()) + " vertices");
  return mesh;
}

}  // namespace tessera
