#include "export/write_mesh.h"

#include <fstream>

#include "base/error.h"
#include "base/file_name.h"
#include "export/glb.h"
#include "export/writers.h"

namespace tessera {

void check_mesh_format(const std::string& file_name) {
  const std::string extension = lowercase_extension(file_name);
  for (const char* known : {"obj", "off", "ply", "stl", "glb"})
    if (extension == known) return;
  throw InputError(file_name +
                   ": cannot tell the output format from the extension; use .obj, "
                   ".ply, .glb, .off or .stl");
}

std::vector<std::uint8_t> encode_mesh(const Mesh& mesh, const std::string& file_name,
                                      const MeshWriteOptions& options) {
  check_mesh_format(file_name);
  const std::string extension = lowercase_extension(file_name);
  if (extension == "obj") return write_obj(mesh);
  if (extension == "off") return write_off(mesh);
  if (extension == "ply") return write_ply(mesh, options.ply_binary);
  if (extension == "stl") return write_stl(mesh);
  Scene scene;
  scene.mesh = mesh;
  return write_glb(scene);
}

std::vector<std::uint8_t> encode_scene(const Scene& scene, const std::string& file_name,
                                       const MeshWriteOptions& options) {
  if (lowercase_extension(file_name) == "glb") return write_glb(scene);
  return encode_mesh(scene.mesh, file_name, options);
}

void write_file_bytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError("cannot write " + path + ": is the folder there and writable?");
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw InputError("cannot write " + path + ": the disk may be full");
}

void write_mesh_file(const std::string& path, const Mesh& mesh, const MeshWriteOptions& options) {
  write_file_bytes(path, encode_mesh(mesh, path, options));
}

}  // namespace tessera
