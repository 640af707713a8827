// Argument parsing shared by the commands: flags with values, switches, positional arguments.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/error.h"

namespace tessera::cli {

class UsageError : public InputError {
 public:
  using InputError::InputError;
  const char* kind() const noexcept override { return "usage"; }
};

// Parsed command line of one command. Options declared with a value take the next argument
// ("--alpha 5" or "--alpha=5"); switches take none. Anything unknown is a UsageError.
struct ParsedArgs {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;
  std::set<std::string> switches;

  bool has(const std::string& name) const { return switches.count(name) || values.count(name); }
  std::string value(const std::string& name, const std::string& fallback = "") const;
  double number(const std::string& name, double fallback) const;
  std::size_t count(const std::string& name, std::size_t fallback) const;
};

ParsedArgs parse_args(const std::vector<std::string>& args, const std::set<std::string>& with_value,
                      const std::set<std::string>& switches, const std::string& command);

}  // namespace tessera::cli
