#include "base/limits.h"

#include "base/error.h"

#include <cstdio>

namespace tessera {

std::string format_seconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", seconds);
  return text;
}

void check_limit(std::uint64_t value, std::uint64_t limit, const std::string& what,
                 const std::string& flag) {
  if (value <= limit) return;
  throw LimitError(what + " has " + std::to_string(value) + ", above the limit of " +
                   std::to_string(limit) + "; raise it with " + flag +
                   " if this machine has the memory, or simplify the input");
}

}  // namespace tessera
