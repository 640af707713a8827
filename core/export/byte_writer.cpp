#include "export/byte_writer.h"

#include <cstdio>
#include <cstdlib>

namespace tessera {

void ByteWriter::text(std::string_view s) {
  const std::size_t at = bytes_.size();
  bytes_.resize(at + s.size());
  if (!s.empty()) std::memcpy(bytes_.data() + at, s.data(), s.size());
}

void ByteWriter::number(double x) {
  char buffer[32];
  int n = std::snprintf(buffer, sizeof buffer, "%.15g", x);
  if (std::strtod(buffer, nullptr) != x) n = std::snprintf(buffer, sizeof buffer, "%.17g", x);
  text(std::string_view(buffer, static_cast<std::size_t>(n)));
}

void ByteWriter::integer(long long x) {
  char buffer[24];
  const int n = std::snprintf(buffer, sizeof buffer, "%lld", x);
  text(std::string_view(buffer, static_cast<std::size_t>(n)));
}

}  // namespace tessera
