// Reading a P1 instance in either of its file forms (instance_json.h, instance_lp.h).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "base/limits.h"
#include "matching/problem.h"

namespace tessera::matching {

// By extension (.json, .lp, any case), else by content (JSON starts with '{'). Throws ParseError,
// LimitError and InputError as the readers do.
MatchingProblem read_instance(std::span<const std::uint8_t> bytes, const std::string& file_name,
                              const Limits& limits);

// The whole file through read_instance(); InputError if it cannot be read.
MatchingProblem read_instance_file(const std::string& path, const Limits& limits);

}  // namespace tessera::matching
