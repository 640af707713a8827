#include "mesh/load.h"

#include "base/error.h"

namespace tessera {
namespace {

// Validation does not know where the mesh came from; its messages get the file name here, keeping
// the error's type.
LoadedMesh validate_loaded(Mesh mesh, const std::string& file_name,
                           const ValidationOptions& options) {
  const std::string prefix = file_name + ": ";
  try {
    ValidationReport report = validate_mesh(mesh, options);
    return {std::move(mesh), std::move(report)};
  } catch (const TopologyError& e) {
    throw TopologyError(prefix + e.what());
  } catch (const GeometryError& e) {
    throw GeometryError(prefix + e.what());
  }
}

}  // namespace

LoadedMesh load_mesh(Bytes bytes, const std::string& file_name, const Limits& limits,
                     const ValidationOptions& options) {
  return validate_loaded(read_mesh(bytes, file_name, limits), file_name, options);
}

LoadedMesh load_mesh_file(const std::string& path, const Limits& limits,
                          const ValidationOptions& options) {
  return validate_loaded(read_mesh_file(path, limits), path, options);
}

}  // namespace tessera
