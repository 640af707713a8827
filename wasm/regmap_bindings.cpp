// Regular-map bindings: the catalog (its text is handed in by the worker, which bundles the shipped
// data/regmaps file), a map's figures, and its planar tiling as SVG. A map is named by a catalog
// name ("R3.1", "R2.4'") or given as a presentation in Conder's text format.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "export/glb.h"
#include "export/print_check.h"
#include "export/write_mesh.h"
#include "guard.h"
#include "js_progress.h"
#include "mesh_display.h"
#include "regmap/catalog.h"
#include "regmap/conder_format.h"
#include "regmap/finite_group.h"
#include "regmap/map_json.h"
#include "regmap/mapped_export.h"
#include "regmap/regular_surface.h"
#include "regmap/surface_export.h"
#include "regmap/target_maps.h"
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

// The last regular surface built, kept for its GLB export.
std::optional<std::pair<std::string, regmap::RegularSurface>>& last_surface() {
  static std::optional<std::pair<std::string, regmap::RegularSurface>> surface;
  return surface;
}

regmap::SurfaceOptions surface_options(const val& options) {
  regmap::SurfaceOptions surface;
  const bool given = !options.isUndefined() && !options.isNull();
  const val base = given ? options["base"] : val::undefined();
  if (!base.isUndefined()) {
    const std::string name = base.isString() ? base.as<std::string>() : "";
    if (name == "platonic") {
      surface.base = regmap::SurfaceBase::Platonic;
    } else if (name == "relax") {
      surface.base = regmap::SurfaceBase::Relax;
    } else if (name != "auto") {
      throw InputError("option 'base' must be 'auto', 'platonic' or 'relax'");
    }
  }
  surface.tube.radius = number_option(options, "tubeRadius", surface.tube.radius);
  // The core checks the range; here only that it is a whole number.
  const double smoothness = number_option(options, "smoothness", surface.tube.smoothness);
  if (!(std::abs(smoothness) < 1e6) || smoothness != std::floor(smoothness))
    throw InputError("option 'smoothness' must be a whole number of quads");
  surface.tube.smoothness = static_cast<int>(smoothness);
  return surface;
}

// { info, stats: surface_stats_json, positions, triangles, triangleFace, tile: Int32Array (per
//   face of the surface mesh: its quarter tube) }
val map_surface(const std::string& spec, const val& options, const val& on_progress) {
  return guard([&] {
    const Enumerated e = enumerate(spec);
    last_surface().reset();
    regmap::RegularSurface surface = regmap::build_regular_surface(
        e.presentation, e.group, surface_options(options), page_limits(), js_progress(on_progress));
    val result = val::object();
    result.set("info", json_to_val(regmap::map_info_json(e.presentation, e.figures, e.seconds)));
    result.set("stats", json_to_val(regmap::surface_stats_json(surface.stats)));
    set_display_arrays(result, surface.mesh);
    result.set("tile", to_typed_array(surface.mesh.face_attributes.at(regmap::kTileAttribute)));
    last_surface().emplace(e.presentation.name, std::move(surface));
    return result;
  });
}

// The last surface as GLB: quarter tubes coloured, per-face _TILE, figures in extras.
val surface_glb() {
  return guard([&] {
    if (!last_surface()) throw InputError("no regular surface has been built yet");
    const auto& [name, surface] = *last_surface();
    return to_typed_array(write_glb(regmap::regular_surface_scene(surface, name)));
  });
}

// The last map drawn on a surface, kept for its export.
struct LastDrawn {
  std::string name;
  regmap::DrawnMap map;
  nlohmann::ordered_json figures;
};
std::optional<LastDrawn>& last_drawn() {
  static std::optional<LastDrawn> drawn;
  return drawn;
}

std::string string_option(const val& options, const char* key) {
  if (options.isUndefined() || options.isNull()) return {};
  const val v = options[key];
  if (v.isUndefined() || v.isNull()) return {};
  if (!v.isString()) throw InputError(std::string("option '") + key + "' must be text");
  return v.as<std::string>();
}

// M drawn through the manifest's pairing when the worker hands one in (options.pairing, its JSON
// text; it is checked like any file), else on the best target that draws it right, of a search
// over options.on or every target of the map's genus. `others`: the other targets found to work.
regmap::DrawnMap draw_chosen(const Enumerated& e, const regmap::ElementWords& words,
                             const val& options, const regmap::MappedMapOptions& drawing,
                             const Progress& progress, std::vector<std::string>& others) {
  const std::string pairing = string_option(options, "pairing");
  const std::string on = string_option(options, "on");
  if (!pairing.empty()) {
    const nlohmann::json json = nlohmann::json::parse(pairing, nullptr, false);
    if (json.is_discarded()) throw InputError("the realization's pairing is not JSON");
    regmap::Realization r;
    r.pairing = regmap::pairing_from_json(json, e.group.order());
    r.target = regmap::find_target(*catalog(), r.pairing.target);
    if (r.target.surface_genus() != e.figures.genus)
      throw InputError("the realization's target " + r.target.name + " has another genus");
    return regmap::draw_realization(e.group, words, r, drawing, page_limits(), progress);
  }
  return regmap::draw_on_best_target(e.group, words, e.figures, e.presentation.name, *catalog(), on,
                                     {}, drawing, page_limits(), progress, &others);
}

// { info, drawn: drawn_map_json, others: [target names], positions, triangles, triangleFace,
//   face: Int32Array (per face of the drawing: M's face), tile: Int32Array (its quarter tube),
//   edges: Float32Array (M's edges, 6 numbers per segment) }
val map_drawn(const std::string& spec, const val& options, const val& on_progress) {
  return guard([&] {
    const auto start = std::chrono::steady_clock::now();
    const Enumerated e = enumerate(spec);
    if (!e.figures.orientable)
      throw InputError(e.presentation.name + " is not orientable: it has no surface to lie on");
    last_drawn().reset();
    const regmap::ElementWords words(e.group);
    std::vector<std::string> others;
    regmap::MappedMapOptions drawing;
    drawing.find_self_intersections = false;
    regmap::DrawnMap map =
        draw_chosen(e, words, options, drawing, js_progress(on_progress), others);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::ordered_json figures =
        regmap::drawn_map_json(e.presentation.name, e.figures, map, seconds);
    val result = val::object();
    result.set("info", json_to_val(regmap::map_info_json(e.presentation, e.figures, e.seconds)));
    result.set("drawn", json_to_val(figures));
    val list = val::array();
    for (const std::string& name : others) list.call<void>("push", name);
    result.set("others", list);
    const Mesh& mesh = map.drawn.mesh;
    set_display_arrays(result, mesh);
    result.set("face", to_typed_array(mesh.face_attributes.at(regmap::kFaceAttribute)));
    result.set("orbit", to_typed_array(mesh.face_attributes.at(regmap::kOrbitAttribute)));
    result.set("tile", to_typed_array(mesh.face_attributes.at(regmap::kTileAttribute)));
    std::vector<float> edges;
    edges.reserve(6 * map.drawn.edge_segments.size());
    for (const auto& [a, b] : map.drawn.edge_segments) {
      for (Index v : {a, b})
        for (int k = 0; k < 3; ++k) edges.push_back(static_cast<float>(mesh.positions[v][k]));
    }
    result.set("edges", to_typed_array(edges));
    last_drawn().emplace(LastDrawn{e.presentation.name, std::move(map), std::move(figures)});
    return result;
  });
}

// The last drawing as a file: format "glb" (faces coloured, _FACE and _TILE per face, edges as
// lines), "ply" (integer face properties face and tile), "obj", or "stl", the solid to print at
// options {sizeMm, wallMm} (export/print_check.h) -> { bytes, print } (print: the check, null
// for the other formats).
val drawn_export(const std::string& format, const val& options, const val& on_progress) {
  return guard([&] {
    if (!last_drawn()) throw InputError("no map has been drawn on a surface yet");
    const LastDrawn& d = *last_drawn();
    const Scene scene = regmap::drawn_map_scene(d.map, d.name, d.figures);
    const std::string file = d.name + "." + format;
    check_mesh_format(file);
    val result = val::object();
    if (format == "stl") {
      PrintOptions print;
      print.size_mm = number_option(options, "sizeMm", print.size_mm);
      print.wall_mm = number_option(options, "wallMm", print.wall_mm);
      const PrintCheck check = check_print(scene.mesh, print, js_progress(on_progress));
      result.set("bytes", to_typed_array(encode_mesh(print_mesh(scene.mesh, check), file)));
      result.set("print", json_to_val(print_check_json(check)));
    } else {
      result.set("bytes", to_typed_array(encode_scene(scene, file)));
      result.set("print", val::null());
    }
    return result;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(tessera_regmap) {
  emscripten::function("regmapLoadCatalog", &load_catalog);
  emscripten::function("regmapInfo", &map_info);
  emscripten::function("regmapTiling", &map_tiling);
  emscripten::function("regmapSurface", &map_surface);
  emscripten::function("regmapSurfaceGlb", &surface_glb);
  emscripten::function("regmapDrawn", &map_drawn);
  emscripten::function("regmapDrawnExport", &drawn_export);
}

}  // namespace tessera::wasm
