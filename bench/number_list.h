// The bench drivers' list arguments: "0,1,5,20" -> {0, 1, 5, 20} (std::stod throws on a bad item).
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace tessera::bench {

inline std::vector<double> number_list(const std::string& list) {
  std::vector<double> out;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

}  // namespace tessera::bench
