#include "base/read_file.h"

#include <fstream>

#include "base/error.h"

namespace tessera {

std::vector<std::uint8_t> read_file_bytes(const std::string& path, const Limits& limits) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError("cannot open " + path + ": no such file, or not readable");
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError("cannot read " + path + ": is it a directory?");
  check_limit(static_cast<std::size_t>(size), limits.max_file_bytes, path + " (bytes)",
              "--max-file-bytes");
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), size))
    throw InputError("cannot read " + path + ": is it a directory, or was it changed while read?");
  return bytes;
}

}  // namespace tessera
