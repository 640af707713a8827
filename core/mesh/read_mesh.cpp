// The format dispatch: extension first, content second.
#include <algorithm>
#include <cstring>
#include <string_view>

#include "base/error.h"
#include "base/file_name.h"
#include "base/text_scan.h"
#include "mesh/readers.h"

namespace tessera {
namespace {

bool starts_with(Bytes bytes, std::string_view prefix) {
  return bytes.size() >= prefix.size() &&
         std::memcmp(bytes.data(), prefix.data(), prefix.size()) == 0;
}

// The first keyword of the first few lines with content that are not comments.
std::optional<MeshFormat> sniff_text(Bytes bytes) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()),
                              std::min<std::size_t>(bytes.size(), 4096));
  std::size_t position = 0;
  for (int lines = 0; lines < 64 && position < text.size(); ++lines) {
    const std::size_t end = std::min(text.find('\n', position), text.size());
    std::string_view keyword;
    Tokens(text.substr(position, end - position)).next(keyword);
    position = end + 1;
    if (keyword.empty() || keyword[0] == '#') continue;
    if (keyword[0] == '{') return MeshFormat::gltf;
    if (keyword == "solid") return MeshFormat::stl;
    if (keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF") return MeshFormat::off;
    if (keyword == "v" || keyword == "vt" || keyword == "vn" || keyword == "f" || keyword == "o" ||
        keyword == "g" || keyword == "mtllib" || keyword == "usemtl" || keyword == "s")
      return MeshFormat::obj;
    return std::nullopt;
  }
  return std::nullopt;
}

std::optional<MeshFormat> sniff(Bytes bytes) {
  if (starts_with(bytes, "glTF")) return MeshFormat::gltf;
  if (starts_with(bytes, "ply\n") || starts_with(bytes, "ply\r\n")) return MeshFormat::ply;
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    for (int i = 3; i >= 0; --i) count = count << 8 | bytes[80 + i];  // little-endian
    if (bytes.size() == 84 + std::uint64_t{count} * 50) return MeshFormat::stl;
  }
  return sniff_text(bytes);
}

}  // namespace

MeshFormat detect_mesh_format(Bytes bytes, const std::string& file_name) {
  const std::string extension = lowercase_extension(file_name);
  if (extension == "obj") return MeshFormat::obj;
  if (extension == "off") return MeshFormat::off;
  if (extension == "ply") return MeshFormat::ply;
  if (extension == "stl") return MeshFormat::stl;
  if (extension == "gltf" || extension == "glb") return MeshFormat::gltf;
  if (const auto format = sniff(bytes)) return *format;
  throw ParseError(file_name +
                   ": cannot tell the mesh format from the name or the content; "
                   "Tessera reads .obj, .off, .ply, .stl, .gltf and .glb files");
}

Mesh read_mesh(Bytes bytes, const std::string& file_name, const Limits& limits,
               const std::string& base_dir) {
  check_limit(bytes.size(), limits.max_file_bytes, file_name + " (bytes)", "--max-file-bytes");
  if (bytes.empty()) throw ParseError(file_name + ": the file is empty");
  if (is_blank(bytes)) throw ParseError(file_name + ": the file holds only whitespace");
  switch (detect_mesh_format(bytes, file_name)) {
    case MeshFormat::obj:
      return read_obj(bytes, file_name, limits);
    case MeshFormat::off:
      return read_off(bytes, file_name, limits);
    case MeshFormat::ply:
      return read_ply(bytes, file_name, limits);
    case MeshFormat::stl:
      return read_stl(bytes, file_name, limits);
    case MeshFormat::gltf:
      return read_gltf(bytes, file_name, limits, base_dir);
  }
  throw Error("unknown mesh format");
}

Mesh read_mesh_file(const std::string& path, const Limits& limits) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(path, limits);
  const std::size_t slash = path.find_last_of('/');
  const std::string base_dir = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  return read_mesh(bytes, path, limits, base_dir);
}

}  // namespace tessera
