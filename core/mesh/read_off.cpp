// Object File Format: a keyword line ("OFF", or a variant such as "COFF", "NOFF", "STOFF" whose
// extra per-vertex values Tessera skips), a counts line "V F E", V vertex lines and F face lines "n
// i_1 ... i_n [colour]". Comments start with '#'.
#include <string_view>

#include "base/error.h"
#include "base/text_scan.h"
#include "mesh/readers.h"

namespace tessera {
namespace {

// The next line with content, comments cut off; false at the end of the file.
bool next_content_line(TextLines& lines, std::string_view& line) {
  while (lines.next(line)) {
    line = line.substr(0, line.find('#'));
    std::string_view token;
    if (Tokens(line).next(token)) return true;
  }
  return false;
}

std::uint64_t parse_count(Tokens& tokens, const TextLines& lines, const char* what) {
  std::string_view token;
  if (!tokens.next(token)) lines.fail(std::string("the header lacks the number of ") + what);
  const auto count = parse_integer(token);
  if (!count || *count < 0)
    lines.fail(std::string("the number of ") + what + " " + quoted(token) +
               " is not a non-negative integer");
  return static_cast<std::uint64_t>(*count);
}

// Reads "V F E" (E ignored) from the header, which may follow the keyword on the same line.
void read_counts(TextLines& lines, std::string_view line, std::uint64_t& vertices,
                 std::uint64_t& faces) {
  Tokens tokens(line);
  std::string_view keyword;
  Tokens peek = tokens;
  peek.next(keyword);
  if (!parse_integer(keyword)) {
    if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF")
      lines.fail("an OFF file starts with the keyword OFF, not " + quoted(keyword));
    if (keyword.find_first_of("4n") != std::string_view::npos)
      lines.fail(quoted(keyword) + " is a higher-dimensional OFF; Tessera reads 3D meshes");
    tokens.next(keyword);
    std::string_view more;
    if (Tokens(tokens).next(more) && more == "BINARY")
      lines.fail("binary OFF is not supported; save the mesh as ASCII OFF, OBJ or PLY");
    if (!Tokens(tokens).next(more)) {
      if (!next_content_line(lines, line))
        lines.fail("the file ends before the counts line \"V F E\"");
      tokens = Tokens(line);
    }
  }
  vertices = parse_count(tokens, lines, "vertices");
  faces = parse_count(tokens, lines, "faces");
}

// The smallest vertex line "0 0 0\n" has 6 bytes, the smallest face line "3 0 1 2\n" 8: a header
// announcing more than the file can hold is refused before anything is allocated.
void check_counts(const TextLines& lines, std::uint64_t vertices, std::uint64_t faces,
                  const Limits& limits) {
  check_limit(vertices, limits.max_vertices, "the vertex list of " + lines.file_name(),
              "--max-vertices");
  check_limit(faces, limits.max_faces, "the face list of " + lines.file_name(), "--max-faces");
  if (6 * vertices + 8 * faces > lines.remaining_bytes() + 1)
    lines.fail("the header announces " + std::to_string(vertices) + " vertices and " +
               std::to_string(faces) + " faces, but only " +
               std::to_string(lines.remaining_bytes()) +
               " bytes follow; the file is truncated or its header is wrong");
}

}  // namespace

Mesh read_off(Bytes bytes, const std::string& file_name, const Limits& limits) {
  TextLines lines(bytes, file_name);
  std::string_view line;
  if (!next_content_line(lines, line)) lines.fail("the file has no OFF header");
  std::uint64_t vertex_count = 0, face_count = 0;
  read_counts(lines, line, vertex_count, face_count);
  check_counts(lines, vertex_count, face_count, limits);

  Mesh mesh;
  mesh.positions.reserve(vertex_count);
  for (std::uint64_t v = 0; v < vertex_count; ++v) {
    if (!next_content_line(lines, line))
      lines.fail("the file ends after " + std::to_string(v) + " of " +
                 std::to_string(vertex_count) + " vertices; it is truncated");
    Tokens tokens(line);
    Eigen::Vector3d p;
    for (int i = 0; i < 3; ++i) {
      std::string_view token;
      const auto value = tokens.next(token) ? parse_double(token) : std::nullopt;
      if (!value) lines.fail("vertex " + std::to_string(v) + " needs three numbers \"x y z\"");
      p[i] = *value;
    }
    if (!p.allFinite())
      throw_non_finite_position(v, file_name + ":" + std::to_string(lines.line_number()));
    mesh.add_vertex(p);
  }

  mesh.face_offsets.reserve(face_count + 1);
  std::vector<Index> corners;
  for (std::uint64_t f = 0; f < face_count; ++f) {
    if (!next_content_line(lines, line))
      lines.fail("the file ends after " + std::to_string(f) + " of " + std::to_string(face_count) +
                 " faces; it is truncated");
    Tokens tokens(line);
    std::string_view token;
    tokens.next(token);
    const auto size = parse_integer(token);
    if (!size || *size < 3)
      lines.fail("face " + std::to_string(f) +
                 " must start with its number of corners (3 or more), not " + quoted(token));
    corners.clear();
    for (std::int64_t i = 0; i < *size; ++i) {
      if (!tokens.next(token))
        lines.fail("face " + std::to_string(f) + " announces " + std::to_string(*size) +
                   " corners but lists " + std::to_string(i));
      const auto v = parse_integer(token);
      if (!v || *v < 0 || static_cast<std::uint64_t>(*v) >= vertex_count)
        lines.fail("face " + std::to_string(f) + " refers to vertex " + quoted(token) +
                   ", but the file has " + std::to_string(vertex_count) +
                   " vertices (numbered from 0)");
      corners.push_back(static_cast<Index>(*v));
    }
    mesh.add_face(corners);
  }
  return mesh;
}

}  // namespace tessera
