// Mesh bindings: sample shapes, reading a user's file, writing a GLB. Thin: each function converts
// JS values to core types, calls core, and converts back (typed arrays in, typed arrays out).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "export/glb.h"
#include "guard.h"
#include "mesh/info.h"
#include "mesh/load.h"
#include "mesh/mesh.h"
#include "mesh/shapes.h"
#include "mesh/validate.h"
#include "mesh_display.h"
#include "session.h"
#include "typed_arrays.h"

namespace tessera::wasm {
namespace {

using emscripten::val;

// The page runs in a browser tab: tighter than the CLI's defaults, well inside the module's
// memory cap (MAXIMUM_MEMORY), so a huge mesh is refused up front instead of killing the tab.
Limits page_limits() {
  Limits limits;
  limits.max_vertices = 2'500'000;
  limits.max_faces = 5'000'000;
  limits.max_file_bytes = 400'000'000;
  return limits;
}

struct Sample {
  const char* name;
  std::function<Mesh()> make;
};

const std::array<Sample, 5>& samples() {
  static const std::array<Sample, 5> all = {{
      {"sphere", [] { return icosphere(3); }},
      {"torus", [] { return torus(1.0, 0.35, 64, 24); }},
      {"genus2", [] { return double_torus(4); }},
      {"part", [] { return mechanical_part(2); }},
      {"annulus", [] { return open_cylinder(1.0, 1.0, 48, 12); }},
  }};
  return all;
}

// The MeshResult of the page: figures plus what the viewer draws, polygons fanned into triangles.
// The mesh becomes the session's mesh, the input of the later stages.
val mesh_result(const std::string& name, const Mesh& mesh, const ValidationReport& report) {
  session().set_mesh(mesh);
  val result = val::object();
  result.set("name", name);
  result.set("info", json_to_val(to_json(mesh_info(mesh, report))));
  set_display_arrays(result, mesh);
  return result;
}

val sample_names() {
  val names = val::array();
  for (const Sample& s : samples()) names.call<void>("push", std::string(s.name));
  return names;
}

val sample_mesh(const std::string& name) {
  return guard([&] {
    for (const Sample& s : samples()) {
      if (name != s.name) continue;
      Mesh mesh = s.make();
      const ValidationReport report = validate_mesh(mesh);
      return mesh_result(name, mesh, report);
    }
    throw InputError("there is no sample shape named '" + name + "'; the samples are " +
                     "sphere, torus, genus2, part, annulus");
  });
}

val load_mesh_bytes(const val& bytes, const std::string& file_name) {
  return guard([&] {
    const std::vector<std::uint8_t> data = from_typed_array<std::uint8_t>(bytes, "bytes");
    LoadedMesh loaded = load_mesh(Bytes(data), file_name, page_limits());
    return mesh_result(file_name, loaded.mesh, loaded.report);
  });
}

// { positions: Float32Array(3V), triangles: Uint32Array(3T), faceIds?: Uint32Array(T),
//   extras?: object } -> Uint8Array (GLB); face ids become the per-face attribute "_FACE".
val export_glb(const val& payload) {
  return guard([&] {
    const std::vector<float> xyz = from_typed_array<float>(payload["positions"], "positions");
    const std::vector<std::uint32_t> tri =
        from_typed_array<std::uint32_t>(payload["triangles"], "triangles");
    if (xyz.size() % 3 != 0 || tri.size() % 3 != 0)
      throw InputError("exportGlb: positions and triangles must hold whole triples");
    Scene scene;
    for (std::size_t i = 0; i < xyz.size(); i += 3)
      scene.mesh.add_vertex(Eigen::Vector3d(xyz[i], xyz[i + 1], xyz[i + 2]));
    for (std::size_t i = 0; i < tri.size(); i += 3) {
      for (int k = 0; k < 3; ++k)
        if (tri[i + k] >= scene.mesh.vertex_count())
          throw InputError("exportGlb: triangle " + std::to_string(i / 3) +
                           " refers to a vertex that does not exist");
      scene.mesh.add_face({tri[i], tri[i + 1], tri[i + 2]});
    }
    if (!payload["faceIds"].isUndefined()) {
      const auto ids = from_typed_array<std::uint32_t>(payload["faceIds"], "faceIds");
      if (ids.size() != scene.mesh.face_count())
        throw InputError("exportGlb: faceIds needs one value per triangle");
      scene.mesh.face_attributes["face"].assign(ids.begin(), ids.end());
    }
    if (!payload["extras"].isUndefined()) scene.extras = val_to_json(payload["extras"]);
    return to_typed_array(write_glb(scene));
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(tessera_mesh) {
  emscripten::function("sampleNames", &sample_names);
  emscripten::function("sampleMesh", &sample_mesh);
  emscripten::function("loadMesh", &load_mesh_bytes);
  emscripten::function("exportGlb", &export_glb);
}

}  // namespace tessera::wasm
