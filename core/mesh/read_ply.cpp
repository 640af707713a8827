// Stanford PLY: an ASCII header of elements and their typed properties, then the elements' data in
// ascii, binary_little_endian or binary_big_endian. Tessera takes x, y, z of "vertex", the
// "vertex_indices" (or "vertex_index") list of "face" and the face's integer properties; every
// other element and property is skipped by its declared type.
#include <limits>
#include <string_view>

#include "base/error.h"
#include "base/text_scan.h"
#include "mesh/byte_reader.h"
#include "mesh/readers.h"

namespace tessera {
namespace {

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };
enum class PlyEncoding { ascii, binary_little_endian, binary_big_endian };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::float32;  // the item type of a list
  bool is_list = false;
  PlyType count_type = PlyType::uint8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;
  std::size_t body_first_line = 0;  // line number of the first body line (ascii)
};

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::int8:
    case PlyType::uint8:
      return 1;
    case PlyType::int16:
    case PlyType::uint16:
      return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32:
      return 4;
    case PlyType::float64:
      return 8;
  }
  return 0;
}

bool is_integer_type(PlyType t) {
  return t != PlyType::float32 && t != PlyType::float64;
}

std::optional<PlyType> parse_type(std::string_view name) {
  static constexpr std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::int8},      {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
      {"uint8", PlyType::uint8},    {"short", PlyType::int16},     {"int16", PlyType::int16},
      {"ushort", PlyType::uint16},  {"uint16", PlyType::uint16},   {"int", PlyType::int32},
      {"int32", PlyType::int32},    {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
      {"float", PlyType::float32},  {"float32", PlyType::float32}, {"double", PlyType::float64},
      {"float64", PlyType::float64}};
  for (const auto& [text, type] : kNames)
    if (name == text) return type;
  return std::nullopt;
}

PlyType expect_type(Tokens& tokens, const TextLines& lines) {
  std::string_view token;
  tokens.next(token);
  const auto type = parse_type(token);
  if (!type) lines.fail("unknown property type " + quoted(token));
  return *type;
}

PlyProperty parse_property(Tokens& tokens, const TextLines& lines) {
  PlyProperty property;
  Tokens peek = tokens;
  std::string_view token;
  peek.next(token);
  if (token == "list") {
    tokens.next(token);
    property.is_list = true;
    property.count_type = expect_type(tokens, lines);
    if (!is_integer_type(property.count_type))
      lines.fail("a list's count type must be an integer type");
  }
  property.type = expect_type(tokens, lines);
  if (!tokens.next(token)) lines.fail("the property has no name");
  property.name = token;
  return property;
}

PlyHeader parse_header(Bytes bytes, const std::string& file_name) {
  TextLines lines(bytes, file_name);
  std::string_view line;
  if (!lines.next(line) || line != "ply") lines.fail("a PLY file starts with the line \"ply\"");
  PlyHeader header;
  bool has_format = false;
  while (lines.next(line)) {
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword) || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (!has_format) lines.fail("the header has no \"format\" line");
      header.body_offset = lines.offset();
      header.body_first_line = lines.line_number() + 1;
      return header;
    }
    if (keyword == "format") {
      std::string_view encoding;
      tokens.next(encoding);
      if (encoding == "ascii")
        header.encoding = PlyEncoding::ascii;
      else if (encoding == "binary_little_endian")
        header.encoding = PlyEncoding::binary_little_endian;
      else if (encoding == "binary_big_endian")
        header.encoding = PlyEncoding::binary_big_endian;
      else
        lines.fail("unknown PLY format " + quoted(encoding));
      has_format = true;
    } else if (keyword == "element") {
      PlyElement& element = header.elements.emplace_back();
      std::string_view token;
      tokens.next(token);
      element.name = token;
      tokens.next(token);
      const auto count = parse_integer(token);
      if (!count || *count < 0)
        lines.fail("element '" + element.name + "' needs a non-negative count, not " +
                   quoted(token));
      element.count = static_cast<std::uint64_t>(*count);
    } else if (keyword == "property") {
      if (header.elements.empty()) lines.fail("a property before any element");
      header.elements.back().properties.push_back(parse_property(tokens, lines));
    } else {
      lines.fail("unknown header line " + quoted(keyword));
    }
  }
  lines.fail("the header never ends (no \"end_header\" line)");
}

// The fewest bytes one instance of the element can take in the body.
std::uint64_t min_element_bytes(const PlyElement& element, PlyEncoding encoding) {
  std::uint64_t bytes = 0;
  for (const PlyProperty& p : element.properties)
    bytes += encoding == PlyEncoding::ascii ? 2 : type_size(p.is_list ? p.count_type : p.type);
  return bytes;
}

// Refuses counts above the limits, and counts that the bytes present cannot hold, before any
// allocation.
void check_sizes(const PlyHeader& header, std::size_t body_bytes, const std::string& file_name,
                 const Limits& limits) {
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex")
      check_limit(element.count, limits.max_vertices, "the vertex element of " + file_name,
                  "--max-vertices");
    if (element.name == "face")
      check_limit(element.count, limits.max_faces, "the face element of " + file_name,
                  "--max-faces");
  }
  std::uint64_t needed = 0;
  for (const PlyElement& element : header.elements) {
    const std::uint64_t per_element = min_element_bytes(element, header.encoding);
    if (per_element > 0 && element.count > (body_bytes + 1) / per_element)
      throw ParseError(file_name + ": the header announces " + std::to_string(element.count) + " " +
                       element.name + " elements, but the " + std::to_string(body_bytes) +
                       " bytes after the header cannot hold them; the file is truncated or its "
                       "header is wrong");
    needed += per_element * element.count;
  }
  if (needed > body_bytes + 1)
    throw ParseError(file_name + ": the header announces elements of at least " +
                     std::to_string(needed) + " bytes, but only " + std::to_string(body_bytes) +
                     " bytes follow; the file is truncated");
}

// Values of the binary body, in the declared byte order.
class BinaryValues {
 public:
  BinaryValues(Bytes bytes, std::size_t offset, bool big_endian, const std::string& file_name)
      : reader_(bytes, offset, big_endian, file_name) {}

  void begin_element() {}

  double number(PlyType t) {
    switch (t) {
      case PlyType::float32:
        return reader_.read<float>("a float");
      case PlyType::float64:
        return reader_.read<double>("a double");
      default:
        return static_cast<double>(integer(t));
    }
  }

  std::int64_t integer(PlyType t) {
    switch (t) {
      case PlyType::int8:
        return reader_.read<std::int8_t>("an int8");
      case PlyType::uint8:
        return reader_.read<std::uint8_t>("a uint8");
      case PlyType::int16:
        return reader_.read<std::int16_t>("an int16");
      case PlyType::uint16:
        return reader_.read<std::uint16_t>("a uint16");
      case PlyType::int32:
        return reader_.read<std::int32_t>("an int32");
      case PlyType::uint32:
        return reader_.read<std::uint32_t>("a uint32");
      default:
        fail("an integer was expected");
    }
  }

  void skip(PlyType t, std::uint64_t n) {
    if (n > reader_.remaining()) reader_.require(n, "a list");  // before multiplying
    reader_.skip(n * type_size(t), "a list");
  }

  void require_list(PlyType t, std::uint64_t n) {
    if (n > reader_.remaining()) reader_.require(n, "a list");
    reader_.require(n * type_size(t), "a list");
  }

  [[noreturn]] void fail(const std::string& message) const { reader_.fail(message); }

 private:
  ByteReader reader_;
};

// Values of the ascii body: one element per line, values separated by whitespace.
class AsciiValues {
 public:
  AsciiValues(Bytes bytes, std::size_t offset, std::size_t first_line, const std::string& file_name)
      : lines_(bytes.subspan(offset), file_name), first_line_(first_line) {}

  void begin_element() {
    std::string_view line;
    do {
      if (!lines_.next(line)) fail("the file ends before all announced elements; it is truncated");
    } while (line.find_first_not_of(" \t") == std::string_view::npos);
    tokens_ = Tokens(line);
  }

  double number(PlyType) {
    const auto value = parse_double(token());
    if (!value) fail(quoted(last_) + " is not a number");
    return *value;
  }

  std::int64_t integer(PlyType) {
    const auto value = parse_integer(token());
    if (!value) fail(quoted(last_) + " is not an integer");
    return *value;
  }

  void skip(PlyType, std::uint64_t n) {
    for (std::uint64_t i = 0; i < n; ++i) token();
  }

  void require_list(PlyType, std::uint64_t) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw ParseError(lines_.file_name() + ":" +
                     std::to_string(first_line_ + lines_.line_number() - 1) + ": " + message);
  }

 private:
  std::string_view token() {
    if (!tokens_.next(last_)) fail("the line has fewer values than the header declares");
    return last_;
  }

  TextLines lines_;
  std::size_t first_line_;
  Tokens tokens_{{}};
  std::string_view last_;
};

bool is_vertex_list(const PlyProperty& p) {
  return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
}

template <class Values>
void skip_property(Values& values, const PlyProperty& p) {
  if (!p.is_list) {
    values.skip(p.type, 1);
    return;
  }
  const std::int64_t n = values.integer(p.count_type);
  if (n < 0) values.fail("negative list length " + std::to_string(n));
  values.skip(p.type, static_cast<std::uint64_t>(n));
}

template <class Values>
void read_vertices(Values& values, const PlyElement& element, Mesh& mesh,
                   const std::string& file_name) {
  int axis_of[3] = {-1, -1, -1};  // property index of x, y, z
  for (std::size_t i = 0; i < element.properties.size(); ++i) {
    const PlyProperty& p = element.properties[i];
    for (int axis = 0; axis < 3; ++axis)
      if (!p.is_list && p.name == std::string(1, static_cast<char>('x' + axis)))
        axis_of[axis] = static_cast<int>(i);
  }
  if (axis_of[0] < 0 || axis_of[1] < 0 || axis_of[2] < 0)
    throw ParseError(file_name + ": the vertex element lacks one of the properties x, y, z");
  mesh.positions.reserve(element.count);
  for (std::uint64_t v = 0; v < element.count; ++v) {
    values.begin_element();
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
      const int axis = i == static_cast<std::size_t>(axis_of[0])   ? 0
                       : i == static_cast<std::size_t>(axis_of[1]) ? 1
                       : i == static_cast<std::size_t>(axis_of[2]) ? 2
                                                                   : -1;
      if (axis >= 0)
        p[axis] = values.number(element.properties[i].type);
      else
        skip_property(values, element.properties[i]);
    }
    if (!p.allFinite()) throw_non_finite_position(v, file_name);
    mesh.add_vertex(p);
  }
}

template <class Values>
void read_faces(Values& values, const PlyElement& element, std::uint64_t vertex_count, Mesh& mesh,
                const std::string& file_name) {
  const PlyProperty* indices = nullptr;
  for (const PlyProperty& p : element.properties) {
    if (is_vertex_list(p))
      indices = &p;
    else if (!p.is_list && is_integer_type(p.type))
      mesh.face_attributes[p.name].reserve(element.count);
  }
  if (!indices) throw ParseError(file_name + ": the face element has no vertex_indices list");
  if (!is_integer_type(indices->type))
    throw ParseError(file_name + ": vertex_indices must be a list of integers");
  mesh.face_offsets.reserve(element.count + 1);
  std::vector<Index> corners;
  for (std::uint64_t f = 0; f < element.count; ++f) {
    values.begin_element();
    for (const PlyProperty& p : element.properties) {
      if (&p == indices) {
        const std::int64_t n = values.integer(p.count_type);
        if (n < 3)
          values.fail("face " + std::to_string(f) + " has " + std::to_string(n) +
                      " corners; a face needs at least 3");
        values.require_list(p.type, static_cast<std::uint64_t>(n));
        corners.clear();
        for (std::int64_t i = 0; i < n; ++i) {
          const std::int64_t v = values.integer(p.type);
          if (v < 0 || static_cast<std::uint64_t>(v) >= vertex_count)
            values.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                        ", but the file has " + std::to_string(vertex_count) +
                        " vertices (numbered from 0)");
          corners.push_back(static_cast<Index>(v));
        }
        mesh.add_face(corners);
      } else if (!p.is_list && is_integer_type(p.type)) {
        const std::int64_t value = values.integer(p.type);
        if (value < std::numeric_limits<std::int32_t>::min() ||
            value > std::numeric_limits<std::int32_t>::max())
          values.fail("face property '" + p.name + "' value " + std::to_string(value) +
                      " does not fit in 32 bits");
        mesh.face_attributes[p.name].push_back(static_cast<std::int32_t>(value));
      } else {
        skip_property(values, p);
      }
    }
  }
  for (const auto& [name, attribute] : mesh.face_attributes)
    if (attribute.size() != mesh.face_count())
      throw ParseError(file_name + ": the face property '" + name + "' is declared twice");
}

template <class Values>
Mesh read_body(Values& values, const PlyHeader& header, const std::string& file_name) {
  const PlyElement* vertices = nullptr;
  const PlyElement* faces = nullptr;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex") vertices = &element;
    if (element.name == "face") faces = &element;
  }
  if (!vertices) throw ParseError(file_name + ": the file has no vertex element");
  if (!faces)
    throw ParseError(
        file_name +
        ": the file has no face element (a point cloud?); Tessera needs a surface mesh");
  Mesh mesh;
  for (const PlyElement& element : header.elements) {
    if (&element == vertices) {
      read_vertices(values, element, mesh, file_name);
    } else if (&element == faces) {
      read_faces(values, element, vertices->count, mesh, file_name);
    } else if (!element.properties.empty()) {
      for (std::uint64_t i = 0; i < element.count; ++i) {
        values.begin_element();
        for (const PlyProperty& p : element.properties) skip_property(values, p);
      }
    }
  }
  return mesh;
}

}  // namespace

Mesh read_ply(Bytes bytes, const std::string& file_name, const Limits& limits) {
  const PlyHeader header = parse_header(bytes, file_name);
  check_sizes(header, bytes.size() - header.body_offset, file_name, limits);
  if (header.encoding == PlyEncoding::ascii) {
    AsciiValues values(bytes, header.body_offset, header.body_first_line, file_name);
    return read_body(values, header, file_name);
  }
  BinaryValues values(bytes, header.body_offset, header.encoding == PlyEncoding::binary_big_endian,
                      file_name);
  return read_body(values, header, file_name);
}

}  // namespace tessera
