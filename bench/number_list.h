// The bench drivers' number arguments: "0,1,5,20" -> {0, 1, 5, 20}. A bad item throws
// std::invalid_argument naming it (the drivers print it and exit with 2).
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tessera::bench {

inline double number(const std::string& item) {
  std::size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(item, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != item.size() || !std::isfinite(value))
    throw std::invalid_argument("'" + item + "' is not a finite number");
  return value;
}

inline std::vector<double> number_list(const std::string& list) {
  std::vector<double> out;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(number(item));
  if (out.empty())
    throw std::invalid_argument("'" + list + "' is no comma-separated list of numbers");
  return out;
}

}  // namespace tessera::bench
