#include "usage.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace tessera::cli {

std::string ParsedArgs::value(const std::string& name, const std::string& fallback) const {
  auto it = values.find(name);
  return it == values.end() ? fallback : it->second;
}

double ParsedArgs::number(const std::string& name, double fallback) const {
  auto it = values.find(name);
  if (it == values.end()) return fallback;
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
    throw UsageError(name + " expects a finite number, got '" + it->second + "'");
  return x;
}

std::size_t ParsedArgs::count(const std::string& name, std::size_t fallback) const {
  auto it = values.find(name);
  if (it == values.end()) return fallback;
  char* end = nullptr;
  errno = 0;
  const unsigned long long x = std::strtoull(it->second.c_str(), &end, 10);
  if (it->second.empty() || it->second[0] == '-' || *end != '\0' || errno == ERANGE)
    throw UsageError(name + " expects a non-negative integer, got '" + it->second + "'");
  return static_cast<std::size_t>(x);
}

ParsedArgs parse_args(const std::vector<std::string>& args, const std::set<std::string>& with_value,
                      const std::set<std::string>& switches, const std::string& command) {
  ParsedArgs parsed;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 2 || a[0] != '-' || a == "--") {
      parsed.positional.push_back(a);
      continue;
    }
    const auto eq = a.find('=');
    const std::string name = a.substr(0, eq);
    if (with_value.count(name)) {
      if (eq != std::string::npos) {
        parsed.values[name] = a.substr(eq + 1);
      } else if (i + 1 < args.size()) {
        parsed.values[name] = args[++i];
      } else {
        throw UsageError(name + " needs a value; run 'tessera " + command + " --help'");
      }
    } else if (switches.count(name) && eq == std::string::npos) {
      parsed.switches.insert(name);
    } else {
      throw UsageError("unknown option '" + a + "' for 'tessera " + command + "'; run 'tessera " +
                       command + " --help'");
    }
  }
  return parsed;
}

}  // namespace tessera::cli
