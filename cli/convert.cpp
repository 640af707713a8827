// tessera convert <in> <out>: reads, validates and writes a mesh in the format of <out>'s
// extension.
#include <cstdio>

#include "commands.h"
#include "export/write_mesh.h"
#include "mesh_input.h"

namespace tessera::cli {
namespace {

void print_convert_help() {
  std::printf(
      "usage: tessera convert <in> <out> [options]\n\n"
      "Reads a mesh (.obj .off .ply .stl .gltf .glb), validates and repairs it as 'tessera info'\n"
      "does (warnings on stderr), and writes it in the format of <out>'s extension:\n"
      ".obj .ply .glb .off .stl. PLY keeps integer face properties; GLB writes them as custom\n"
      "attributes (_NAME).\n\n"
      "  --ascii              write PLY as ascii (default: binary little-endian)\n"
      "%s\n"
      "Exit codes: 0 ok, 1 internal error, 2 bad input (the message says what and where).\n",
      kMeshInputHelp);
}

}  // namespace

int convert_command(const Args& args) {
  const ParsedArgs parsed =
      parse_args(args, mesh_input_options(), {"--ascii", "--help", "-h"}, "convert");
  if (parsed.has("--help") || parsed.has("-h")) {
    print_convert_help();
    return 0;
  }
  if (parsed.positional.size() != 2)
    throw UsageError(
        "'tessera convert' takes an input and an output file; run 'tessera convert --help'");
  const LoadedMesh loaded = load_mesh_argument(parsed.positional[0], parsed);
  for (const std::string& warning : loaded.report.warnings)
    std::fprintf(stderr, "tessera: warning: %s\n", warning.c_str());
  MeshWriteOptions options;
  options.ply_binary = !parsed.has("--ascii");
  // Encoding first: an unknown output extension is reported before any file is touched.
  write_file_bytes(parsed.positional[1], encode_mesh(loaded.mesh, parsed.positional[1], options));
  return 0;
}

}  // namespace tessera::cli
