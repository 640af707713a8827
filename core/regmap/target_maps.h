// The maps a source map can be drawn on (thesis Sec. 9.5-9.6): any map T whose regular surface,
// its tubified edge graph, has the source's genus E_T - V_T + 1. Beside the catalog's maps and
// their duals, the maps of genus 0 and 1 that the census lacks, as presentations generated here:
//   the five Platonic maps {3,3}, {4,3}, {3,4}, {5,3}, {3,5} (surfaces of genus 3, 5, 7, 11, 19);
//   the hosohedra {2,n}, two junctions of valence n (genus n - 1);
//   the reflexible torus maps {4,4}_(b,0) and {4,4}_(b,b) (extra relator (R S^-1)^b, resp.
//   (R S^-1 R^-1 S)^b), {3,6}_(b,0) and {3,6}_(b,b) ((R S^-2)^b, resp. (R S^-2 R^-1 S^2)^b), and
//   their duals {6,3}_(b,0), {6,3}_(b,b).
// The dihedra {n,2} are no targets: their junctions of valence 2 do not make a surface (q >= 3).
// The chiral torus maps {4,4}_(b,c), 0 < c < b, have no reflections to pair.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "regmap/catalog.h"
#include "regmap/presentation.h"

namespace tessera::regmap {

enum class TargetKind { Platonic, Hosohedron, Torus, Catalog };
const char* to_string(TargetKind kind);

struct TargetMap {
  std::string name;  // "Cube", "{2,6}", "{4,4}_(2,0)", "R2.1'"
  TargetKind kind = TargetKind::Catalog;
  Presentation presentation;  // named as the target
  std::size_t vertices = 0;   // junctions of its surface
  std::size_t edges = 0;      // tubes
  std::size_t faces = 0;
  int surface_genus() const { return static_cast<int>(edges) - static_cast<int>(vertices) + 1; }
  int valence() const { return presentation.q; }
};

// Every target whose surface has genus 2..max_genus: the generated ones, then the catalog's maps
// and their duals (valence 3 or more), in that order.
std::vector<TargetMap> all_targets(const Catalog& catalog, int max_genus);

// The target named `name` (a generated name as above, or a catalog name with or without a prime).
// Throws InputError listing the name forms when there is none.
TargetMap find_target(const Catalog& catalog, const std::string& name);

}  // namespace tessera::regmap
