// glTF 2.0 and GLB through tinygltf. tinygltf parses the JSON and gathers the buffers; every
// accessor is then checked here against its buffer view and buffer before a byte is read, since
// neither a file's JSON nor tinygltf guarantees that.
#include <cstring>
#include <functional>
#include <limits>

#include <Eigen/Geometry>

#include "base/error.h"
#include "mesh/exact_welder.h"
#include "mesh/readers.h"
#include "mesh/tinygltf.h"

namespace tessera {
namespace {

// External buffers are read only when reading from a path (base_dir set), and within the limits.
struct FileAccess {
  const Limits* limits;
  bool allowed;
};

bool file_exists(const std::string& path, void* user) {
  return static_cast<FileAccess*>(user)->allowed && tinygltf::FileExists(path, nullptr);
}

std::string expand_path(const std::string& path, void*) {
  return path;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  const FileAccess& access = *static_cast<FileAccess*>(user);
  if (!access.allowed) {
    *err =
        "external files cannot be read when the glTF comes from memory; use a .glb or embedded "
        "buffers";
    return false;
  }
  try {
    *out = read_file_bytes(path, *access.limits);
    return true;
  } catch (const InputError& e) {
    *err = e.what();
    return false;
  }
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "writing is not allowed while reading";
  return false;
}

// Tessera needs no images: accept them without decoding.
bool ignore_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                  const unsigned char*, int, void*) {
  return true;
}

std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (char& c : text)
    if (c == '\n') c = ';';
  return text;
}

// A checked window onto an accessor's elements.
struct AccessorView {
  const unsigned char* first = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int component_type = 0;
  int type = 0;
};

class GltfMeshBuilder {
 public:
  GltfMeshBuilder(const tinygltf::Model& model, const std::string& file_name, const Limits& limits)
      : model_(model), file_name_(file_name), limits_(limits) {}

  Mesh build() {
    if (model_.scenes.empty()) {
      // No scene: the meshes as they are.
      for (std::size_t m = 0; m < model_.meshes.size(); ++m)
        add_mesh(static_cast<int>(m), Eigen::Matrix4d::Identity());
    } else {
      const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (scene >= static_cast<int>(model_.scenes.size()))
        fail("the default scene " + std::to_string(scene) + " does not exist");
      visited_.assign(model_.nodes.size(), false);
      for (int node : model_.scenes[scene].nodes) add_node(node, Eigen::Matrix4d::Identity());
    }
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw ParseError(file_name_ + ": " + message);
  }

  Eigen::Matrix4d local_transform(const tinygltf::Node& node) const {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    if (node.matrix.size() == 16) {
      for (int i = 0; i < 16; ++i) m(i % 4, i / 4) = node.matrix[i];  // column-major
      return m;
    }
    Eigen::Affine3d t = Eigen::Affine3d::Identity();
    if (node.translation.size() == 3)
      t.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
      t.rotate(
          Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2])
              .normalized());
    if (node.scale.size() == 3)
      t.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
    return t.matrix();
  }

  // glTF nodes form trees; a node reached twice (a cycle or a shared child) is refused, which also
  // bounds the work on hostile files.
  void add_node(int node_index, const Eigen::Matrix4d& parent) {
    if (node_index < 0 || node_index >= static_cast<int>(model_.nodes.size()))
      fail("node " + std::to_string(node_index) + " does not exist");
    if (visited_[node_index])
      fail("node " + std::to_string(node_index) +
           " is reached twice; glTF nodes must form trees without cycles");
    visited_[node_index] = true;
    const tinygltf::Node& node = model_.nodes[node_index];
    const Eigen::Matrix4d world = parent * local_transform(node);
    if (!world.allFinite())
      fail("node " + std::to_string(node_index) + " has a non-finite transform");
    if (node.mesh >= 0) add_mesh(node.mesh, world);
    for (int child : node.children) add_node(child, world);
  }

  void add_mesh(int mesh_index, const Eigen::Matrix4d& world) {
    if (mesh_index >= static_cast<int>(model_.meshes.size()))
      fail("mesh " + std::to_string(mesh_index) + " does not exist");
    const auto& primitives = model_.meshes[mesh_index].primitives;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      const std::string where =
          "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(p);
      add_primitive(primitives[p], world, where);
    }
  }

  AccessorView view(int accessor_index, const std::string& where) const {
    if (accessor_index < 0 || accessor_index >= static_cast<int>(model_.accessors.size()))
      fail(where + ": accessor " + std::to_string(accessor_index) + " does not exist");
    const tinygltf::Accessor& a = model_.accessors[accessor_index];
    if (a.sparse.isSparse) fail(where + ": sparse accessors are not supported");
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model_.bufferViews.size()))
      fail(where + ": the accessor has no valid bufferView");
    const tinygltf::BufferView& bv = model_.bufferViews[a.bufferView];
    if (bv.buffer < 0 || bv.buffer >= static_cast<int>(model_.buffers.size()))
      fail(where + ": bufferView " + std::to_string(a.bufferView) + " has no valid buffer");
    const std::size_t buffer_size = model_.buffers[bv.buffer].data.size();
    const int component_size = tinygltf::GetComponentSizeInBytes(a.componentType);
    const int components = tinygltf::GetNumComponentsInType(a.type);
    if (component_size <= 0 || components <= 0) fail(where + ": the accessor has an invalid type");
    const std::size_t element = static_cast<std::size_t>(component_size) * components;
    const std::size_t stride = bv.byteStride ? bv.byteStride : element;
    if (stride < element) fail(where + ": the bufferView's byteStride is smaller than an element");
    if (bv.byteLength > buffer_size || bv.byteOffset > buffer_size - bv.byteLength)
      fail(where + ": bufferView " + std::to_string(a.bufferView) +
           " reaches past the end of its buffer (" + std::to_string(buffer_size) + " bytes)");
    AccessorView v;
    v.stride = stride;
    v.count = a.count;
    v.component_type = a.componentType;
    v.type = a.type;
    if (a.count > 0) {
      const std::size_t room = bv.byteLength;
      if (a.byteOffset > room || element > room - a.byteOffset ||
          a.count - 1 > (room - a.byteOffset - element) / stride)
        fail(where + ": the accessor's " + std::to_string(a.count) +
             " elements reach past the end of bufferView " + std::to_string(a.bufferView));
      v.first = model_.buffers[bv.buffer].data.data() + bv.byteOffset + a.byteOffset;
    }
    return v;
  }

  std::vector<Eigen::Vector3d> read_positions(const tinygltf::Primitive& primitive,
                                              const std::string& where) const {
    const auto it = primitive.attributes.find("POSITION");
    if (it == primitive.attributes.end()) fail(where + ": the primitive has no POSITION attribute");
    const AccessorView v = view(it->second, where + " POSITION");
    if (v.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT || v.type != TINYGLTF_TYPE_VEC3)
      fail(where + ": POSITION must be float VEC3 (quantized positions are not supported)");
    check_limit(mesh_.vertex_count() + v.count, limits_.max_vertices,
                "the vertex list of " + file_name_, "--max-vertices");
    std::vector<Eigen::Vector3d> positions(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
      float xyz[3];
      std::memcpy(xyz, v.first + i * v.stride, sizeof xyz);
      positions[i] = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
    }
    return positions;
  }

  std::vector<std::uint32_t> read_indices(const tinygltf::Primitive& primitive,
                                          std::size_t vertices, const std::string& where) const {
    std::vector<std::uint32_t> indices;
    if (primitive.indices < 0) {
      indices.resize(vertices);
      for (std::size_t i = 0; i < vertices; ++i) indices[i] = static_cast<std::uint32_t>(i);
      return indices;
    }
    const AccessorView v = view(primitive.indices, where + " indices");
    if (v.type != TINYGLTF_TYPE_SCALAR) fail(where + ": indices must be scalars");
    check_limit(v.count / 3, limits_.max_faces, "the face list of " + file_name_, "--max-faces");
    indices.resize(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
      const unsigned char* at = v.first + i * v.stride;
      std::uint32_t index = 0;
      switch (v.component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          index = *at;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          std::uint16_t x;
          std::memcpy(&x, at, 2);
          index = x;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
          std::memcpy(&index, at, 4);
          break;
        default:
          fail(where + ": indices must be unsigned bytes, shorts or ints");
      }
      if (index >= vertices)
        fail(where + ": index " + std::to_string(i) + " is " + std::to_string(index) +
             ", but the primitive has " + std::to_string(vertices) + " vertices");
      indices[i] = index;
    }
    return indices;
  }

  // Triangles of a triangle list, strip or fan, as index triples into the primitive.
  static std::vector<std::array<std::uint32_t, 3>> triangles(
      int mode, const std::vector<std::uint32_t>& idx) {
    std::vector<std::array<std::uint32_t, 3>> out;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (std::size_t i = 0; i + 2 < idx.size(); i += 3)
        out.push_back({idx[i], idx[i + 1], idx[i + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (std::size_t i = 0; i + 2 < idx.size(); ++i)
        out.push_back(i % 2 == 0 ? std::array{idx[i], idx[i + 1], idx[i + 2]}
                                 : std::array{idx[i + 1], idx[i], idx[i + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      for (std::size_t i = 1; i + 1 < idx.size(); ++i) out.push_back({idx[0], idx[i], idx[i + 1]});
    }
    return out;
  }

  void add_primitive(const tinygltf::Primitive& primitive, const Eigen::Matrix4d& world,
                     const std::string& where) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN)
      return;  // points and lines are not part of the surface
    const std::vector<Eigen::Vector3d> positions = read_positions(primitive, where);
    const std::vector<std::uint32_t> indices = read_indices(primitive, positions.size(), where);
    const auto tris = triangles(mode, indices);
    check_limit(mesh_.face_count() + tris.size(), limits_.max_faces,
                "the face list of " + file_name_, "--max-faces");
    // A mirroring transform turns the faces inside out; reversing them keeps normals outward.
    const bool mirrored = world.topLeftCorner<3, 3>().determinant() < 0;
    std::vector<Index> vertex_of(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const Eigen::Vector3d p = (world * positions[i].homogeneous()).head<3>();
      if (!p.allFinite())
        fail(where + ": vertex " + std::to_string(i) +
             " has a non-finite coordinate (NaN or infinity)");
      vertex_of[i] = welder_.vertex(p);
    }
    for (const auto& t : tris) {
      if (mirrored)
        mesh_.add_face({vertex_of[t[0]], vertex_of[t[2]], vertex_of[t[1]]});
      else
        mesh_.add_face({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
    }
  }

  const tinygltf::Model& model_;
  const std::string& file_name_;
  const Limits& limits_;
  Mesh mesh_;
  std::vector<bool> visited_;
  // glTF splits a vertex wherever an attribute (normal, uv) changes; Tessera keeps positions only.
  ExactWelder welder_{mesh_};
};

}  // namespace

Mesh read_gltf(Bytes bytes, const std::string& file_name, const Limits& limits,
               const std::string& base_dir) {
  if (bytes.size() > std::numeric_limits<unsigned int>::max())
    check_limit(bytes.size(), std::numeric_limits<unsigned int>::max(), file_name,
                "a smaller file");
  FileAccess access{&limits, !base_dir.empty()};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(ignore_image, nullptr);
  loader.SetFsCallbacks({file_exists, expand_path, read_whole_file, refuse_write, &access});
  tinygltf::Model model;
  std::string error, warning;
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok =
      binary
          ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), size, base_dir)
          : loader.LoadASCIIFromString(&model, &error, &warning,
                                       reinterpret_cast<const char*>(bytes.data()), size, base_dir);
  if (!ok)
    throw ParseError(file_name + ": not a valid " + (binary ? "GLB" : "glTF") +
                     " file: " + one_line(error.empty() ? warning : error));
  return GltfMeshBuilder(model, file_name, limits).build();
}

}  // namespace tessera
