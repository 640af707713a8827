// Quad mesh bindings (thesis Ch. 8) on the session's last layout: what the size target does not
// change (the sides, their chains' parametric lengths, each patch unfolded with its Wachspress
// coordinates: remesh::RemeshPrep) is made on the first remesh of a layout and kept, so that a new
// quad count only solves (8.1)-(8.3) again and places the points (the page's slider); the input's
// side of the Hausdorff distance is kept per mesh. The quad mesh of the last target is kept for
// its OBJ, PLY and GLB, written by the same core code as `tessera remesh -o`. The figures are
// `tessera remesh --json`'s. Progress goes to an optional JS onProgress(stage, fraction).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "export/write_mesh.h"
#include "guard.h"
#include "js_progress.h"
#include "layout/layout_scene.h"
#include "remesh/remesh_json.h"
#include "session.h"
#include "typed_arrays.h"

namespace tessera::wasm {
namespace {

using emscripten::val;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// options: one of { quads, lambda, edgeLength } (as the CLI's --quads, --lambda, --edge-length).
remesh::SizeTarget size_target(const val& options) {
  const auto given = [&](const char* key) {
    return !options.isUndefined() && !options.isNull() && !options[key].isUndefined();
  };
  if (given("quads") + given("lambda") + given("edgeLength") > 1)
    throw InputError("give one of the options 'quads', 'lambda' and 'edgeLength'");
  remesh::SizeTarget target;
  const double quads = number_option(options, "quads", 0);
  if (given("quads") && !(quads >= 1 && quads <= 1e8 && quads == std::floor(quads)))
    throw InputError("option 'quads' must be a whole number in [1, 100000000]");
  target.quads = static_cast<std::size_t>(quads);
  target.edge_length = number_option(options, "edgeLength", 0);
  if (given("edgeLength") && !(target.edge_length > 0))
    throw InputError("option 'edgeLength' must be a positive number");
  target.lambda = number_option(options, "lambda", target.lambda);
  if (!(target.lambda > 0)) throw InputError("option 'lambda' must be a positive number");
  return target;
}

Session& session_with_layout() {
  Session& s = session();
  if (!s.resolve_cache.last || !s.layout_graph || !s.param)
    throw InputError("there is no quad layout to remesh: run the layout first");
  return s;
}

std::vector<float> vertex_floats(const Mesh& mesh) {
  std::vector<float> xyz;
  xyz.reserve(3 * mesh.vertex_count());
  for (const Eigen::Vector3d& p : mesh.positions)
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(p[k]));
  return xyz;
}

std::vector<float> patch_colors(std::size_t patch_count) {
  std::vector<float> colors;
  for (std::size_t p = 0; p < patch_count; ++p) {
    const Color c = layout::patch_color(static_cast<std::int32_t>(p));
    colors.insert(colors.end(), {c.x(), c.y(), c.z()});
  }
  return colors;
}

// The quad mesh of the session's layout for a size target (size_target()'s options).
// -> { info: remesh_json + prepared_before (the layout's prep was kept from an earlier remesh),
//      positions: Float32Array (3 per vertex), quads: Uint32Array (4 vertex indices per quad,
//      counterclockwise), patch: Int32Array (per quad, the layout's patch), patchColors:
//      Float32Array (3 per patch, the layout's colours) }
val remesh_layout(const val& options, const val& on_progress) {
  return guard([&] {
    Session& s = session_with_layout();
    const remesh::SizeTarget target = size_target(options);
    const Progress progress = js_progress(on_progress);
    const layout::QuadLayout& layout = *s.resolve_cache.last;
    nlohmann::ordered_json seconds;
    const bool prepared_before = s.remesh_prep.has_value();
    s.quad_mesh.reset();
    auto start = Clock::now();
    if (!prepared_before) {
      progress.step("remesh prep", 0);
      s.remesh_prep = remesh::prepare_remesh(layout);
    }
    seconds["prep"] = seconds_since(start);
    progress.step("remesh", 0);
    remesh::QuadMesh quads = remesh::remesh_prepared(layout, *s.remesh_prep, target);
    for (const layout::StageSeconds& step : quads.seconds) seconds[step.stage] = step.seconds;

    progress.step("hausdorff", 0);
    start = Clock::now();
    if (!s.hausdorff) s.hausdorff = std::make_unique<remesh::HausdorffReference>(*s.mesh);
    const double hausdorff = s.hausdorff->relative_to(quads.mesh);
    seconds["hausdorff"] = seconds_since(start);
    const long input_euler = long(s.mesh->vertex_count()) - long(s.connectivity->edge_count()) +
                             long(s.mesh->face_count());
    nlohmann::ordered_json info = remesh::remesh_json(quads, input_euler, hausdorff, seconds);
    info["prepared_before"] = prepared_before;

    const Mesh& mesh = quads.mesh;
    std::vector<std::uint32_t> corners(mesh.face_vertices.begin(), mesh.face_vertices.end());
    val result = val::object();
    result.set("info", json_to_val(info));
    result.set("positions", to_typed_array(vertex_floats(mesh)));
    result.set("quads", to_typed_array(corners));
    result.set("patch", to_typed_array(mesh.face_attributes.at("patch")));
    result.set("patchColors", to_typed_array(patch_colors(quads.patch_count)));
    s.quad_mesh = std::move(quads);
    return result;
  });
}

// The last quad mesh as a file: format "obj", "ply" (integer face property patch) or "glb"
// (_PATCH per face), the bytes `tessera remesh -o quads.<format>` writes.
val remesh_export(const std::string& format) {
  return guard([&] {
    const Session& s = session();
    if (!s.quad_mesh) throw InputError("there is no quad mesh to export: remesh the layout first");
    if (format != "obj" && format != "ply" && format != "glb")
      throw InputError("a quad mesh exports as obj, ply or glb, not '" + format + "'");
    return to_typed_array(encode_mesh(s.quad_mesh->mesh, "quads." + format));
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(tessera_remesh) {
  emscripten::function("remeshLayout", &remesh_layout);
  emscripten::function("remeshExport", &remesh_export);
}

}  // namespace tessera::wasm
