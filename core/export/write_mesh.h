// Writing a mesh (or a scene) to the format its output file name asks for: .obj .off .ply .stl .glb.
//
// In:  a mesh, a file name or path (the extension decides, any case).
// Out: the bytes (encode_mesh) or the file (write_mesh_file).
// Throws InputError for an unknown extension (naming the known ones) or a file that cannot be
// written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "export/scene.h"
#include "mesh/mesh.h"

namespace tessera {

struct MeshWriteOptions {
  bool ply_binary = true;  // false: ascii PLY
};

std::vector<std::uint8_t> encode_mesh(const Mesh& mesh, const std::string& file_name,
                                      const MeshWriteOptions& options = {});

// Throws the InputError of encode_mesh() when the extension of `file_name` names no format, so
// that a long computation can refuse an output name before it starts.
void check_mesh_format(const std::string& file_name);

// A scene in the format of `file_name`: GLB carries all of it (glb.h), the other formats its mesh.
std::vector<std::uint8_t> encode_scene(const Scene& scene, const std::string& file_name,
                                       const MeshWriteOptions& options = {});

// The bytes to the path; throws InputError if the file cannot be written.
void write_file_bytes(const std::string& path, const std::vector<std::uint8_t>& bytes);

void write_mesh_file(const std::string& path, const Mesh& mesh,
                     const MeshWriteOptions& options = {});

}  // namespace tessera
