// What every command that reads a mesh shares: the options for limits and welding, their help
// text, and the call that reads and validates the mesh.
#pragma once

#include <set>
#include <string>

#include "mesh/load.h"
#include "usage.h"

namespace tessera::cli {

// Option names (each takes a value) to merge into a command's parse_args() set.
std::set<std::string> mesh_input_options();

// Help lines describing those options.
extern const char* const kMeshInputHelp;

// load_mesh_file() with the limits and validation options given on the command line.
LoadedMesh load_mesh_argument(const std::string& path, const ParsedArgs& args);

// load_mesh_argument() for the commands that work on triangles: the load warnings go to stderr and
// polygons are split into triangles.
Mesh load_triangle_mesh_argument(const std::string& path, const ParsedArgs& args);

}  // namespace tessera::cli
