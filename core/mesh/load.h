// Reading and validating in one call: what the CLI and the page do with a user's mesh file.
//
// In:  the file's bytes and name (or a path), limits, validation options.
// Out: the repaired mesh (validate.h) and the report of what was repaired.
// Throws the readers' ParseError/GeometryError/LimitError and validation's TopologyError/
// GeometryError, every message starting with the file name.
#pragma once

#include <string>

#include "base/limits.h"
#include "mesh/mesh.h"
#include "mesh/readers.h"
#include "mesh/validate.h"

namespace tessera {

struct LoadedMesh {
  Mesh mesh;
  ValidationReport report;
};

LoadedMesh load_mesh(Bytes bytes, const std::string& file_name, const Limits& limits = {},
                     const ValidationOptions& options = {});
LoadedMesh load_mesh_file(const std::string& path, const Limits& limits = {},
                          const ValidationOptions& options = {});

}  // namespace tessera
