// Regular-map bindings: the catalog (its text is handed in by the worker, which bundles the shipped
// data/regmaps file), a map's figures, and its planar tiling as SVG. A map is named by a catalog
// name ("R3.1", "R2.4'") or given as a presentation in Conder's text format.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <chrono>
#include <optional>
#include <string>

#include "guard.h"
#include "regmap/catalog.h"
#include "regmap/conder_format.h"
#include "regmap/finite_group.h"
#include "regmap/map_json.h"
#include "regmap/tiling_svg.h"
#include "regmap/triangle_tiling.h"
#include "typed_arrays.h"

namespace tessera::wasm {
namespace {

using emscripten::val;

// The catalog of this module instance (one worker): parsed once, kept for lookups.
std::optional<regmap::Catalog>& catalog() {
  static std::optional<regmap::Catalog> parsed;
  return parsed;
}

// Coset enumeration in a browser tab: a time limit short enough that a typo in a hand-typed
// presentation (an infinite group) answers quickly, a table that fits the memory cap.
Limits page_limits() {
  Limits limits;
  limits.max_coset_table = 2'000'000;
  limits.max_coset_seconds = 10.0;
  return limits;
}

val load_catalog(const std::string& text) {
  return guard([&] {
    catalog() = regmap::parse_catalog(text, "catalog_g2-101.tsv");
    val rows = val::array();
    for (const regmap::CatalogEntry& e : *catalog())
      rows.call<void>("push", json_to_val(regmap::catalog_row_json(e)));
    return rows;
  });
}

// A catalog name, or else the text of a presentation in Conder's format.
regmap::Presentation resolve(const std::string& spec) {
  const bool is_name = !spec.empty() && spec[0] == 'R' && spec.find_first_of(" \n[:") == spec.npos;
  if (!is_name) return regmap::parse_conder_entry(spec, "presentation");
  if (!catalog()) throw InputError("the catalog is not loaded yet; reload the page");
  return regmap::presentation_of(regmap::find_map(*catalog(), spec));
}

struct Enumerated {
  regmap::Presentation presentation;
  regmap::FiniteGroup group;
  regmap::MapFigures figures;
  double seconds = 0;
};

Enumerated enumerate(const std::string& spec) {
  Enumerated e{resolve(spec), {}, {}, 0};
  const auto start = std::chrono::steady_clock::now();
  e.group = regmap::enumerate_group(e.presentation, page_limits());
  e.figures = regmap::map_figures(e.group);
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  regmap::check_stated_figures(e.presentation, e.figures);
  return e;
}

val map_info(const std::string& spec) {
  return guard([&] {
    const Enumerated e = enumerate(spec);
    return json_to_val(regmap::map_info_json(e.presentation, e.figures, e.seconds));
  });
}

// { info, svg, polygon: { triangles, boundaryPairs, euler, boundaryCycles } }: a hyperbolic or
// torus map's polygon is a disk (euler 1, one boundary cycle), a spherical map's closes up.
val map_tiling(const std::string& spec) {
  return guard([&] {
    const Enumerated e = enumerate(spec);
    const regmap::TriangleTiling tiling = regmap::build_tiling(e.group, page_limits());
    const regmap::PolygonShape shape = regmap::polygon_shape(tiling);
    val result = val::object();
    result.set("info", json_to_val(regmap::map_info_json(e.presentation, e.figures, e.seconds)));
    result.set("svg", regmap::tiling_svg(e.group, tiling, e.presentation.name));
    val polygon = val::object();
    polygon.set("triangles", tiling.size());
    polygon.set("boundaryPairs", tiling.pairs.size());
    polygon.set("euler", static_cast<double>(shape.euler));
    polygon.set("boundaryCycles", shape.boundary_cycles);
    result.set("polygon", polygon);
    return result;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(tessera_regmap) {
  emscripten::function("regmapLoadCatalog", &load_catalog);
  emscripten::function("regmapInfo", &map_info);
  emscripten::function("regmapTiling", &map_tiling);
}

}  // namespace tessera::wasm
