// The shape of every fuzz target: the input goes through one parser of Tessera with small limits.
// A tessera::Error (or bad_alloc turned into one by the core) is the expected way to refuse bad
// input; anything else -- a crash, a sanitizer report, another exception -- is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "base/error.h"
#include "base/limits.h"

namespace tessera::fuzz {

// Small enough that each input finishes in milliseconds, large enough to reach every code path.
inline Limits fuzz_limits() {
  Limits limits;
  limits.max_vertices = 100'000;
  limits.max_faces = 200'000;
  limits.max_file_bytes = 1 << 22;
  limits.max_coset_table = 20'000;
  limits.max_coset_seconds = 0.5;
  return limits;
}

template <class F>
int run_refusing(F&& body) {
  try {
    body();
  } catch (const tessera::Error&) {
  }
  return 0;
}

}  // namespace tessera::fuzz

#define TESSERA_FUZZ_TARGET(body)                                                     \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    const std::span<const std::uint8_t> bytes(data, size);                            \
    return tessera::fuzz::run_refusing([&] { body; });                                \
  }
