// Reading a whole file into memory, with the size limit checked before reading: what the mesh
// readers, the field reader and the matching instance readers share.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/limits.h"

namespace tessera {

// The whole file; throws InputError if it cannot be read, LimitError if it is above
// limits.max_file_bytes (checked before reading).
std::vector<std::uint8_t> read_file_bytes(const std::string& path, const Limits& limits);

}  // namespace tessera
