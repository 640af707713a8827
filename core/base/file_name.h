// File-name helpers shared by the code that picks a format from a name (mesh readers, writers).
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace tessera {

// The extension after the last dot of the last path component, in lower case ("" if none):
// "dir.v2/Mesh.OBJ" -> "obj".
inline std::string lowercase_extension(const std::string& file_name) {
  const std::size_t slash = file_name.find_last_of("/\\");
  const std::size_t dot = file_name.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string extension = file_name.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace tessera
