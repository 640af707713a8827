#include "matching/instance_file.h"

#include <algorithm>
#include <cctype>

#include "base/read_file.h"
#include "matching/instance_json.h"
#include "matching/instance_lp.h"

namespace tessera::matching {

namespace {

bool has_extension(const std::string& name, const std::string& extension) {
  if (name.size() < extension.size()) return false;
  return std::equal(extension.rbegin(), extension.rend(), name.rbegin(), [](char a, char b) {
    return a == std::tolower(static_cast<unsigned char>(b));
  });
}

bool starts_like_json(std::span<const std::uint8_t> bytes) {
  const auto first =
      std::find_if(bytes.begin(), bytes.end(), [](std::uint8_t b) { return !std::isspace(b); });
  return first != bytes.end() && *first == '{';
}

}  // namespace

MatchingProblem read_instance(std::span<const std::uint8_t> bytes, const std::string& file_name,
                              const Limits& limits) {
  const bool json = has_extension(file_name, ".json") ||
                    (!has_extension(file_name, ".lp") && starts_like_json(bytes));
  return json ? read_instance_json(bytes, file_name, limits)
              : read_instance_lp(bytes, file_name, limits);
}

MatchingProblem read_instance_file(const std::string& path, const Limits& limits) {
  return read_instance(read_file_bytes(path, limits), path, limits);
}

}  // namespace tessera::matching
