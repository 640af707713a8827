#include "base/limits.h"

#include "base/error.h"

namespace tessera {

void check_limit(std::uint64_t value, std::uint64_t limit, const std::string& what,
                 const std::string& flag) {
  if (value <= limit) return;
  throw LimitError(what + " has " + std::to_string(value) + ", above the limit of " +
                   std::to_string(limit) + "; raise it with " + flag +
                   " if this machine has the memory, or simplify the input");
}

}  // namespace tessera
