// Writing a mesh to the format its output file name asks for: .obj .off .ply .stl .glb.
//
// In:  a mesh, a file name or path (the extension decides, any case).
// Out: the bytes (encode_mesh) or the file (write_mesh_file).
// Throws InputError for an unknown extension (naming the known ones) or a file that cannot be
// written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace tessera {

struct MeshWriteOptions {
  bool ply_binary = true;  // false: ascii PLY
};

std::vector<std::uint8_t> encode_mesh(const Mesh& mesh, const std::string& file_name,
                                      const MeshWriteOptions& options = {});

// The bytes to the path; throws InputError if the file cannot be written.
void write_file_bytes(const std::string& path, const std::vector<std::uint8_t>& bytes);

void write_mesh_file(const std::string& path, const Mesh& mesh,
                     const MeshWriteOptions& options = {});

}  // namespace tessera
