// Cross field and seamless parameterization of the session's mesh (the last one loaded or
// sampled). Progress goes to an optional JS callback onProgress(stage, fraction).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <chrono>
#include <string>
#include <vector>

#include "field/design.h"
#include "guard.h"
#include "js_progress.h"
#include "param/param_json.h"
#include "session.h"
#include "typed_arrays.h"

namespace tessera::wasm {
namespace {

using emscripten::val;

FieldOptions field_options(const val& options) {
  FieldOptions field;
  const val align = options.isUndefined() || options.isNull() ? val::undefined() : options["align"];
  if (!align.isUndefined()) {
    const std::string name = align.isString() ? align.as<std::string>() : "";
    if (name == "curvature") {
      field.align = FieldAlignment::curvature;
    } else if (name != "smooth") {
      throw InputError("option 'align' must be 'smooth' or 'curvature'");
    }
  }
  field.sharp_degrees = number_option(options, "sharp", field.sharp_degrees);
  field.curvature_weight = number_option(options, "curvatureWeight", field.curvature_weight);
  return field;
}

Session& session_with_mesh() {
  Session& s = session();
  if (!s.mesh) throw InputError("no mesh is loaded: open a file or pick a sample first");
  if (!s.connectivity) s.connectivity = build_connectivity(*s.mesh);
  if (!s.frames) s.frames = face_frames(*s.mesh);
  return s;
}

// { info: singularities_json + seconds, directions: Float32Array(3F) (u_T per triangle),
//   singularityVertices: Uint32Array, singularityValences: Int32Array }
val cross_field(const val& options, const val& on_progress) {
  return guard([&] {
    Session& s = session_with_mesh();
    s.clear_param();
    const auto start = std::chrono::steady_clock::now();
    s.field = design_cross_field(*s.mesh, *s.connectivity, *s.frames, field_options(options),
                                 js_progress(on_progress));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<float> directions;
    directions.reserve(3 * s.field->direction.size());
    for (const Eigen::Vector3d& d : s.field->direction)
      for (int k = 0; k < 3; ++k) directions.push_back(static_cast<float>(d[k]));
    std::vector<std::uint32_t> vertices;
    std::vector<std::int32_t> valences;
    for (const Singularity& sing : s.field->singularities) {
      vertices.push_back(sing.vertex);
      valences.push_back(sing.valence);
    }
    val result = val::object();
    nlohmann::ordered_json info = singularities_json(*s.field);
    info["seconds"] = seconds;
    result.set("info", json_to_val(info));
    result.set("directions", to_typed_array(directions));
    result.set("singularityVertices", to_typed_array(vertices));
    result.set("singularityValences", to_typed_array(valences));
    return result;
  });
}

// { info: param_json, uv: Float32Array(2 per corner, corners in triangle order) }; computes the
// field first (with default options) if there is none.
val seamless_param(const val& options, const val& on_progress) {
  return guard([&] {
    Session& s = session_with_mesh();
    const Progress progress = js_progress(on_progress);
    if (!s.field)
      s.field = design_cross_field(*s.mesh, *s.connectivity, *s.frames, FieldOptions(), progress);
    ParamOptions param_options;
    param_options.h_relative = number_option(options, "h", param_options.h_relative);
    if (!(param_options.h_relative > 0 && param_options.h_relative <= 1))
      throw InputError("option 'h' (relative to the bounding-box diagonal) must be in (0, 1]");
    s.clear_param();
    s.param = seamless_parameterization(*s.mesh, *s.connectivity, *s.frames, *s.field,
                                        param_options, progress);
    std::vector<float> uv;
    uv.reserve(2 * s.param->uv.size());
    for (const Eigen::Vector2d& c : s.param->uv) {
      uv.push_back(static_cast<float>(c.x()));
      uv.push_back(static_cast<float>(c.y()));
    }
    val result = val::object();
    result.set("info", json_to_val(param_json(*s.field, *s.param)));
    result.set("uv", to_typed_array(uv));
    return result;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(tessera_field) {
  emscripten::function("crossField", &cross_field);
  emscripten::function("seamlessParam", &seamless_param);
}

}  // namespace tessera::wasm
