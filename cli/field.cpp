// tessera field <mesh>: a cross field of the mesh, its singularities and the Poincare-Hopf check
// (thesis Sec. 6.3).
#include <cstdio>

#include "commands.h"
#include "field/cross_field.h"
#include "field_input.h"
#include "mesh_input.h"
#include "param/param_json.h"

namespace tessera::cli {
namespace {

void print_field_help() {
  std::printf(
      "usage: tessera field <mesh> [--align smooth|curvature] [--sharp DEG] [--field FILE]\n"
      "                     [--json] [options]\n\n"
      "Computes a smooth cross field (or reads one), its period jumps and vertex indices, and\n"
      "prints the singularities: vertices of index k/4 != 0, valence 4 - k inside (3 for +1/4,\n"
      "5 for -1/4), 2 - k on the boundary, where the field is read relative to the boundary.\n"
      "The indices sum to the Euler characteristic (Poincare-Hopf).\n\n"
      "%s"
      "  --json               one JSON object on stdout with the keys euler_characteristic,\n"
      "                       index_sum, singularities (a list of {vertex, index, valence})\n"
      "%s\n"
      "Exit codes: 0 ok, 1 internal error, 2 bad input (the message says what and where).\n",
      kFieldInputHelp, kMeshInputHelp);
}

}  // namespace

int field_command(const Args& args) {
  std::set<std::string> values = mesh_input_options();
  values.merge(field_input_options());
  const ParsedArgs parsed = parse_args(args, values, {"--json", "--help", "-h"}, "field");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_field_help();
    return 0;
  }
  if (parsed.positional.size() != 1)
    throw UsageError("'tessera field' takes one mesh file; run 'tessera field --help'");
  const Mesh mesh = load_triangle_mesh_argument(parsed.positional[0], parsed);
  const Connectivity connectivity = build_connectivity(mesh);
  const FaceFrames frames = face_frames(mesh);
  const CrossField field =
      field_from_arguments(mesh, connectivity, frames, parsed, stderr_progress());
  if (parsed.has("--json"))
    std::printf("%s\n", singularities_json(field).dump(2).c_str());
  else
    std::printf("%s", singularities_text(mesh, field).c_str());
  return 0;
}

}  // namespace tessera::cli
