#include "regmap/finite_group.h"

#include <string>

#include "base/error.h"

namespace tessera::regmap {

using enum Letter;

Element FiniteGroup::times(Element g, const Word& w) const {
  for (Letter x : w) g = times(g, x);
  return g;
}

FiniteGroup enumerate_group(const Presentation& presentation, const Limits& limits,
                            const Progress& progress, EnumerationStats* stats) {
  FiniteGroup group;
  group.p = presentation.p;
  group.q = presentation.q;
  group.table = enumerate_cosets(defining_relators(presentation), limits, progress, stats);
  return group;
}

Orbits orbits(const FiniteGroup& group, const std::vector<Word>& generators) {
  Orbits result;
  result.label.assign(group.order(), -1);
  std::vector<Element> stack;
  for (std::size_t start = 0; start < group.order(); ++start) {
    if (result.label[start] >= 0) continue;
    const auto label = static_cast<std::int32_t>(result.count++);
    result.label[start] = label;
    stack.push_back(static_cast<Element>(start));
    while (!stack.empty()) {
      const Element g = stack.back();
      stack.pop_back();
      for (const Word& w : generators) {
        const Element h = group.times(g, w);
        if (result.label[static_cast<std::size_t>(h)] >= 0) continue;
        result.label[static_cast<std::size_t>(h)] = label;
        stack.push_back(h);
      }
    }
  }
  return result;
}

Orbits vertex_orbits(const FiniteGroup& group) {
  return orbits(group, {{S}, {T}});
}
Orbits edge_orbits(const FiniteGroup& group) {
  return orbits(group, {{T, S}, {R, T}});
}
Orbits face_orbits(const FiniteGroup& group) {
  return orbits(group, {{R}, {T}});
}

std::size_t element_order(const FiniteGroup& group, const Word& w) {
  Element g = group.times(0, w);
  std::size_t k = 1;
  while (g != 0) {
    g = group.times(g, w);
    ++k;
  }
  return k;
}

namespace {

void check_generator_order(const FiniteGroup& group, Letter x, int expected, const char* what) {
  const std::size_t found = element_order(group, {x});
  if (found != static_cast<std::size_t>(expected))
    throw InputError("the relators make " + to_string(x) + " of order " + std::to_string(found) +
                     " instead of " + std::to_string(expected) +
                     ": the group is not that of a map of type {" + std::to_string(group.p) + "," +
                     std::to_string(group.q) + "} (" + what + "); check the relators");
}

void check_orbit_count(std::size_t counted, std::size_t order, std::size_t stabiliser,
                       const char* what) {
  if (counted * stabiliser != order)
    throw InputError("the group of order " + std::to_string(order) + " has " +
                     std::to_string(counted) + " " + what + " where a regular map has " +
                     std::to_string(order) + "/" + std::to_string(stabiliser) +
                     ": the relators collapse the map; check them");
}

}  // namespace

MapFigures map_figures(const FiniteGroup& group) {
  check_generator_order(group, R, group.p, "R rotates a p-gon");
  check_generator_order(group, S, group.q, "S rotates about a q-valent vertex");
  MapFigures f;
  f.order = group.order();
  f.vertices = vertex_orbits(group).count;
  f.edges = edge_orbits(group).count;
  f.faces = face_orbits(group).count;
  check_orbit_count(f.vertices, f.order, 2 * static_cast<std::size_t>(group.q), "vertices");
  check_orbit_count(f.edges, f.order, 4, "edges");
  check_orbit_count(f.faces, f.order, 2 * static_cast<std::size_t>(group.p), "faces");
  f.euler = static_cast<long long>(f.vertices) - static_cast<long long>(f.edges) +
            static_cast<long long>(f.faces);
  f.orientable = orbits(group, {{R}, {S}}).count == 2;
  f.genus = f.orientable ? static_cast<int>((2 - f.euler) / 2) : 0;
  f.petrie = element_order(group, {R, S, T});
  return f;
}

void check_stated_figures(const Presentation& presentation, const MapFigures& figures) {
  const std::string name = presentation.name.empty() ? "the presentation" : presentation.name;
  if (presentation.stated_order != 0 && presentation.stated_order != figures.order)
    throw InputError(name + " states order " + std::to_string(presentation.stated_order) +
                     " but its relators define a group of order " + std::to_string(figures.order) +
                     "; check the relators");
  if (presentation.stated_petrie != 0 &&
      static_cast<std::size_t>(presentation.stated_petrie) != figures.petrie)
    throw InputError(name + " states Petrie length " + std::to_string(presentation.stated_petrie) +
                     " but R*S*T has order " + std::to_string(figures.petrie) +
                     " in its group; check the relators");
}

}  // namespace tessera::regmap
