// tessera info <mesh> [--json]: the figures of a mesh.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "mesh/info.h"
#include "mesh_input.h"

namespace tessera::cli {
namespace {

void print_info_help() {
  std::printf(
      "usage: tessera info <mesh> [--json] [options]\n\n"
      "Reads a mesh (.obj .off .ply .stl .gltf .glb), validates and repairs it, and prints its\n"
      "vertices, edges, faces and face sizes, components, boundary loops, genus, Euler\n"
      "characteristic, manifold and orientation status, bounding box and diagonal, and "
      "warnings.\n\n"
      "  --json               one JSON object on stdout with the keys vertices, faces, edges,\n"
      "                       face_sizes, components, boundary_loops, genus,\n"
      "                       euler_characteristic, manifold, oriented (false: faces had to be\n"
      "                       flipped), bbox_min, bbox_max, bbox_diagonal, warnings\n"
      "%s\n"
      "Exit codes: 0 ok, 1 internal error, 2 bad input (the message says what and where).\n",
      kMeshInputHelp);
}

}  // namespace

int info_command(const Args& args) {
  const ParsedArgs parsed =
      parse_args(args, mesh_input_options(), {"--json", "--help", "-h"}, "info");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_info_help();
    return 0;
  }
  if (parsed.positional.size() != 1)
    throw UsageError("'tessera info' takes one mesh file; run 'tessera info --help'");
  const LoadedMesh loaded = load_mesh_argument(parsed.positional[0], parsed);
  const MeshInfo info = mesh_info(loaded.mesh, loaded.report);
  if (parsed.has("--json"))
    std::printf("%s\n", to_json(info).dump(2).c_str());
  else
    std::printf("%s", to_text(info).c_str());
  return 0;
}

}  // namespace tessera::cli
