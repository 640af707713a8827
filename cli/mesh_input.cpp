#include "mesh_input.h"

#include <cstdio>

#include "field_input.h"

namespace tessera::cli {

std::set<std::string> mesh_input_options() {
  return {"--max-vertices", "--max-faces", "--max-file-bytes", "--weld-tolerance"};
}

const char* const kMeshInputHelp =
    "  --max-vertices N     refuse meshes with more vertices (default 4000000)\n"
    "  --max-faces N        refuse meshes with more faces (default 8000000)\n"
    "  --max-file-bytes N   refuse larger files (default 1500000000)\n"
    "  --weld-tolerance X   weld boundary vertices closer than X times the bounding-box\n"
    "                       diagonal, closing cracks (default 1e-7; 0 welds identical\n"
    "                       positions only; -1 never welds); welds that would make the mesh\n"
    "                       non-manifold or non-orientable are kept apart, with a warning\n";

LoadedMesh load_mesh_argument(const std::string& path, const ParsedArgs& args) {
  Limits limits;
  limits.max_vertices = args.count("--max-vertices", limits.max_vertices);
  limits.max_faces = args.count("--max-faces", limits.max_faces);
  limits.max_file_bytes = args.count("--max-file-bytes", limits.max_file_bytes);
  ValidationOptions options;
  options.weld_tolerance = args.number("--weld-tolerance", options.weld_tolerance);
  return load_mesh_file(path, limits, options);
}

Mesh load_triangle_mesh_argument(const std::string& path, const ParsedArgs& args) {
  const LoadedMesh loaded = load_mesh_argument(path, args);
  for (const std::string& warning : loaded.report.warnings)
    std::fprintf(stderr, "tessera: warning: %s\n", warning.c_str());
  return triangles_of(loaded.mesh);
}

}  // namespace tessera::cli
