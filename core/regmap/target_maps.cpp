#include "regmap/target_maps.h"

#include <array>
#include <cstdio>

#include "base/error.h"

namespace tessera::regmap {

using enum Letter;

const char* to_string(TargetKind kind) {
  switch (kind) {
    case TargetKind::Platonic:
      return "platonic";
    case TargetKind::Hosohedron:
      return "hosohedron";
    case TargetKind::Torus:
      return "torus";
    case TargetKind::Catalog:
      return "catalog";
  }
  return "catalog";
}

namespace {

TargetMap generated(std::string name, TargetKind kind, int p, int q, std::vector<Word> relators,
                    std::size_t vertices, std::size_t faces) {
  TargetMap target;
  target.name = name;
  target.kind = kind;
  target.presentation.name = std::move(name);
  target.presentation.p = p;
  target.presentation.q = q;
  target.presentation.relators = std::move(relators);
  target.vertices = vertices;
  target.faces = faces;
  target.edges = vertices * static_cast<std::size_t>(q) / 2;
  target.presentation.stated_order = 4 * target.edges;
  return target;
}

std::vector<TargetMap> platonic_targets() {
  struct Solid {
    const char* name;
    int p, q;
    std::size_t vertices, faces;
  };
  constexpr std::array<Solid, 5> solids = {{{"Tetrahedron", 3, 3, 4, 4},
                                            {"Cube", 4, 3, 8, 6},
                                            {"Octahedron", 3, 4, 6, 8},
                                            {"Dodecahedron", 5, 3, 20, 12},
                                            {"Icosahedron", 3, 5, 12, 20}}};
  std::vector<TargetMap> targets;
  for (const Solid& s : solids)
    targets.push_back(generated(s.name, TargetKind::Platonic, s.p, s.q, {}, s.vertices, s.faces));
  return targets;
}

std::string torus_name(int p, int q, int b, int c) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "{%d,%d}_(%d,%d)", p, q, b, c);
  return buffer;
}

// The torus map {p,q}_(b,c) with extra relator translation^b, if its surface's genus is at most
// max_genus; returns whether it was added.
bool add_torus_map(int p, int q, int b, int c, const Word& translation, std::size_t vertices,
                   std::size_t faces, int max_genus, std::vector<TargetMap>& targets) {
  TargetMap t = generated(torus_name(p, q, b, c), TargetKind::Torus, p, q, {power(translation, b)},
                          vertices, faces);
  if (t.surface_genus() > max_genus) return false;
  targets.push_back(std::move(t));
  return true;
}

// {6,3}_(b,c) as the dual of {3,6}_(b,c).
bool add_hexagonal_map(int b, int c, const Word& translation, std::size_t vertices,
                       std::size_t faces, int max_genus, std::vector<TargetMap>& targets) {
  Presentation triangular;
  triangular.p = 3;
  triangular.q = 6;
  triangular.relators = {power(translation, b)};
  TargetMap t = generated(torus_name(6, 3, b, c), TargetKind::Torus, 6, 3,
                          dual(triangular).relators, vertices, faces);
  if (t.surface_genus() > max_genus) return false;
  targets.push_back(std::move(t));
  return true;
}

void add_torus_maps(int max_genus, std::vector<TargetMap>& targets) {
  const Word square = {R, Si}, square_skew = {R, Si, Ri, S};
  const Word triangle = {R, Si, Si}, triangle_skew = {R, Si, Si, Ri, S, S};
  for (int b = 1;; ++b) {
    const auto n = static_cast<std::size_t>(b * b);
    bool any = add_torus_map(4, 4, b, 0, square, n, n, max_genus, targets);
    any |= add_torus_map(4, 4, b, b, square_skew, 2 * n, 2 * n, max_genus, targets);
    any |= add_torus_map(3, 6, b, 0, triangle, n, 2 * n, max_genus, targets);
    any |= add_torus_map(3, 6, b, b, triangle_skew, 3 * n, 6 * n, max_genus, targets);
    any |= add_hexagonal_map(b, 0, triangle, 2 * n, n, max_genus, targets);
    any |= add_hexagonal_map(b, b, triangle_skew, 6 * n, 3 * n, max_genus, targets);
    if (!any) return;
  }
}

TargetMap catalog_target(const CatalogEntry& entry) {
  TargetMap target;
  target.name = entry.name;
  target.kind = TargetKind::Catalog;
  target.presentation = presentation_of(entry);
  target.vertices = entry.vertices;
  target.edges = entry.edges;
  target.faces = entry.faces;
  return target;
}

}  // namespace

std::vector<TargetMap> all_targets(const Catalog& catalog, int max_genus) {
  std::vector<TargetMap> targets;
  for (TargetMap& t : platonic_targets()) {
    if (t.surface_genus() <= max_genus) targets.push_back(std::move(t));
  }
  for (int n = 3; n - 1 <= max_genus; ++n)
    targets.push_back(generated("{2," + std::to_string(n) + "}", TargetKind::Hosohedron, 2, n, {},
                                2, static_cast<std::size_t>(n)));
  add_torus_maps(max_genus, targets);
  for (const CatalogEntry& entry : catalog) {
    for (const CatalogEntry& e : {entry, dual(entry)}) {
      TargetMap t = catalog_target(e);
      if (t.valence() >= 3 && t.surface_genus() <= max_genus) targets.push_back(std::move(t));
    }
  }
  return targets;
}

TargetMap find_target(const Catalog& catalog, const std::string& name) {
  if (!name.empty() && name[0] == 'R') return catalog_target(find_map(catalog, name));
  for (TargetMap& t : all_targets({}, 1'000)) {
    if (t.name == name) return t;
  }
  throw InputError("no target map named '" + name +
                   "'; a target is a catalog name (R2.1, R2.1'), a Platonic solid (Tetrahedron, "
                   "Cube, Octahedron, Dodecahedron, Icosahedron), a hosohedron {2,n} or a torus "
                   "map {4,4}_(b,0), {4,4}_(b,b), {3,6}_(b,0), {3,6}_(b,b), {6,3}_(b,0), "
                   "{6,3}_(b,b)");
}

}  // namespace tessera::regmap
