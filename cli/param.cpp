// tessera param <mesh>: the seamless Poisson parameterization of the mesh with a cross field
// (thesis Sec. 6.5, 6.6, App. A), its figures, and optionally an OBJ with per-corner uv.
#include <chrono>
#include <cstdio>

#include "commands.h"
#include "export/write_mesh.h"
#include "export/writers.h"
#include "field_input.h"
#include "mesh_input.h"
#include "param/param_json.h"
#include "param/seamless_param.h"

namespace tessera::cli {
namespace {

void print_param_help() {
  std::printf(
      "usage: tessera param <mesh> [--h REL] [--json] [-o param.obj] [field options] [options]\n\n"
      "Computes a cross field (or reads one), cuts the mesh open along a cut graph through the\n"
      "singularities, and solves for the seamless Poisson parameterization: per-corner (u, v)\n"
      "whose gradients follow the field, with transitions J^r uv + t across the cut (r the\n"
      "field's period jump, t free). Triangles around singularities and flipped triangles get\n"
      "the bisector injectivity constraints (solved with GLPK).\n\n"
      "  --h REL              sizing: one parameter unit is REL times the bounding-box diagonal\n"
      "                       (default 0.01)\n"
      "  -o FILE.obj          write the mesh with the parameterization as per-corner vt\n"
      "  --json               one JSON object on stdout with the keys euler_characteristic,\n"
      "                       index_sum, singularities, flipped_triangles,\n"
      "                       flipped_outside_singular_rings, max_seam_error (relative to the\n"
      "                       parameter domain), seconds (per step), and "
      "flipped_before_injectivity,\n"
      "                       energy, h\n"
      "%s%s\n"
      "Exit codes: 0 ok, 1 internal error, 2 bad input (the message says what and where).\n",
      kFieldInputHelp, kMeshInputHelp);
}

std::string param_text(const SeamlessParam& param) {
  char text[512];
  std::snprintf(text, sizeof text,
                "flipped triangles %zu (%zu before the injectivity constraints, %zu outside the "
                "singularities' one-rings)\nmax seam error %.3g (relative), energy %.4g, h %.4g\n",
                param.flipped_triangles, param.flipped_before_injectivity,
                param.flipped_outside_singular_rings, param.max_seam_error, param.energy, param.h);
  std::string result = text;
  for (const StepTime& t : param.seconds) {
    std::snprintf(text, sizeof text, "  %-12s %.3f s\n", t.step.c_str(), t.seconds);
    result += text;
  }
  return result;
}

}  // namespace

int param_command(const Args& args) {
  std::set<std::string> values = mesh_input_options();
  values.merge(field_input_options());
  values.insert({"--h", "-o"});
  const ParsedArgs parsed = parse_args(args, values, {"--json", "--help", "-h"}, "param");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_param_help();
    return 0;
  }
  if (parsed.positional.size() != 1)
    throw UsageError("'tessera param' takes one mesh file; run 'tessera param --help'");
  ParamOptions options;
  options.h_relative = parsed.number("--h", options.h_relative);
  if (!(options.h_relative > 0)) throw UsageError("--h expects a positive number");
  const Mesh mesh = load_triangle_mesh_argument(parsed.positional[0], parsed);
  const Progress progress = stderr_progress();

  const auto start = std::chrono::steady_clock::now();
  const Connectivity connectivity = build_connectivity(mesh);
  const FaceFrames frames = face_frames(mesh);
  const CrossField field = field_from_arguments(mesh, connectivity, frames, parsed, progress);
  const double field_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SeamlessParam param =
      seamless_parameterization(mesh, connectivity, frames, field, options, progress);
  param.seconds.insert(param.seconds.begin(), {"field", field_seconds});

  if (parsed.has("-o")) write_file_bytes(parsed.value("-o"), write_obj(mesh, param.uv));
  if (parsed.has("--json")) {
    std::printf("%s\n", param_json(field, param).dump(2).c_str());
  } else {
    std::printf("%s%s", singularities_text(mesh, field).c_str(), param_text(param).c_str());
  }
  return 0;
}

}  // namespace tessera::cli
