#include <algorithm>
#include <cctype>
#include <limits>
#include <sstream>

#include "base/error.h"
#include "export/glb.h"
#include "mesh/geometry.h"
#include "mesh/tinygltf.h"

namespace tessera {
namespace {

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

tinygltf::Value to_value(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::boolean:
      return tinygltf::Value(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned: {
      const double x = j.get<double>();
      if (x >= std::numeric_limits<int>::min() && x <= std::numeric_limits<int>::max())
        return tinygltf::Value(j.get<int>());
      return tinygltf::Value(x);
    }
    case nlohmann::json::value_t::number_float:
      return tinygltf::Value(j.get<double>());
    case nlohmann::json::value_t::string:
      return tinygltf::Value(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      tinygltf::Value::Array array;
      for (const auto& item : j) array.push_back(to_value(item));
      return tinygltf::Value(std::move(array));
    }
    case nlohmann::json::value_t::object: {
      tinygltf::Value::Object object;
      for (const auto& [key, item] : j.items()) object[key] = to_value(item);
      return tinygltf::Value(std::move(object));
    }
    default:
      return tinygltf::Value();
  }
}

// "patch" -> "_PATCH": glTF requires custom attribute names to start with an underscore.
std::string attribute_name(const std::string& name) {
  std::string out = "_";
  for (char c : name) out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

Eigen::Vector3f unit_or_up(const Eigen::Vector3d& n) {
  // The glTF validator requires unit normals; a face without area has none, any unit vector will
  // do.
  return n.squaredNorm() > 0 ? n.cast<float>().normalized() : Eigen::Vector3f(0, 0, 1);
}

// Every triangle of the fan triangulation, with the face it comes from.
struct Triangle {
  std::array<Index, 3> v;
  Index face;
};

std::vector<Triangle> fan_triangles(const Mesh& mesh) {
  std::vector<Triangle> triangles;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      triangles.push_back({{face[0], face[i], face[i + 1]}, f});
  }
  return triangles;
}

// Builds the tinygltf model: one buffer, one buffer view per accessor.
class ModelBuilder {
 public:
  explicit ModelBuilder(const Eigen::Vector3d& origin) : origin_(origin) {
    model_.buffers.emplace_back();
    model_.asset.version = "2.0";
    model_.asset.generator = "Tessera";
    model_.scenes.emplace_back();
    model_.defaultScene = 0;
  }

  int positions(const std::vector<Eigen::Vector3d>& points) {
    std::vector<float> data;
    data.reserve(3 * points.size());
    std::vector<double> lo(3, std::numeric_limits<double>::max());
    std::vector<double> hi(3, std::numeric_limits<double>::lowest());
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector3f q = (p - origin_).cast<float>();
      for (int i = 0; i < 3; ++i) {
        data.push_back(q[i]);
        lo[i] = std::min<double>(lo[i], q[i]);
        hi[i] = std::max<double>(hi[i], q[i]);
      }
    }
    const int a = floats(data, TINYGLTF_TYPE_VEC3);
    model_.accessors[a].minValues = lo;
    model_.accessors[a].maxValues = hi;
    return a;
  }

  int vectors(const std::vector<Eigen::Vector3f>& vectors) {
    std::vector<float> data;
    data.reserve(3 * vectors.size());
    for (const Eigen::Vector3f& v : vectors) data.insert(data.end(), v.data(), v.data() + 3);
    return floats(data, TINYGLTF_TYPE_VEC3);
  }

  int floats(const std::vector<float>& data, int type) {
    const int components = tinygltf::GetNumComponentsInType(type);
    return accessor(data.data(), data.size() * sizeof(float), kArrayBuffer,
                    TINYGLTF_COMPONENT_TYPE_FLOAT, type, data.size() / components);
  }

  int indices(const std::vector<std::uint32_t>& data) {
    return accessor(data.data(), data.size() * sizeof(std::uint32_t), kElementArrayBuffer,
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, data.size());
  }

  int material(const std::string& name, const Color& color, bool double_sided) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {color.x(), color.y(), color.z(), 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 0.7;
    m.doubleSided = double_sided;
    model_.materials.push_back(m);
    return static_cast<int>(model_.materials.size() - 1);
  }

  // A node named `name` holding a mesh with one primitive.
  void node(const std::string& name, tinygltf::Primitive primitive) {
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(std::move(primitive));
    model_.meshes.push_back(std::move(mesh));
    tinygltf::Node node;
    node.name = name;
    node.mesh = static_cast<int>(model_.meshes.size() - 1);
    node.translation = {origin_.x(), origin_.y(), origin_.z()};
    model_.nodes.push_back(std::move(node));
    model_.scenes[0].nodes.push_back(static_cast<int>(model_.nodes.size() - 1));
  }

  tinygltf::Model& model() { return model_; }

 private:
  int accessor(const void* data, std::size_t bytes, int target, int component_type, int type,
               std::size_t count) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();  // stays a multiple of 4: every component has 4 bytes
    view.byteLength = bytes;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), begin, begin + bytes);
    model_.bufferViews.push_back(view);
    tinygltf::Accessor a;
    a.bufferView = static_cast<int>(model_.bufferViews.size() - 1);
    a.componentType = component_type;
    a.type = type;
    a.count = count;
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size() - 1);
  }

  Eigen::Vector3d origin_;
  tinygltf::Model model_;
};

void check_sizes(const Scene& scene) {
  if (!scene.vertex_colors.empty() && scene.vertex_colors.size() != scene.mesh.vertex_count())
    throw Error("write_glb: " + std::to_string(scene.vertex_colors.size()) +
                " vertex colours for " + std::to_string(scene.mesh.vertex_count()) + " vertices");
  if (!scene.face_colors.empty() && scene.face_colors.size() != scene.mesh.face_count())
    throw Error("write_glb: " + std::to_string(scene.face_colors.size()) + " face colours for " +
                std::to_string(scene.mesh.face_count()) + " faces");
  for (const auto& [name, values] : scene.mesh.face_attributes)
    if (values.size() != scene.mesh.face_count())
      throw Error("write_glb: face attribute '" + name + "' has the wrong size");
}

// Shared vertices: positions, smooth normals, vertex colours; the mesh reads back unchanged.
tinygltf::Primitive shared_vertex_primitive(const Scene& scene, ModelBuilder& builder) {
  const Mesh& mesh = scene.mesh;
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] = builder.positions(mesh.positions);
  std::vector<Eigen::Vector3f> normals;
  for (const Eigen::Vector3d& n : vertex_normals(mesh)) normals.push_back(unit_or_up(n));
  primitive.attributes["NORMAL"] = builder.vectors(normals);
  if (!scene.vertex_colors.empty())
    primitive.attributes["COLOR_0"] = builder.vectors(scene.vertex_colors);
  std::vector<std::uint32_t> indices;
  for (const Triangle& t : fan_triangles(mesh))
    indices.insert(indices.end(), t.v.begin(), t.v.end());
  primitive.indices = builder.indices(indices);
  return primitive;
}

// Vertices split per triangle, so that per-face values become per-vertex attributes.
tinygltf::Primitive split_vertex_primitive(const Scene& scene, ModelBuilder& builder) {
  const Mesh& mesh = scene.mesh;
  const std::vector<Triangle> triangles = fan_triangles(mesh);
  const std::vector<Eigen::Vector3d> face_normal_list = face_normals(mesh);
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3f> normals, colors;
  std::vector<std::vector<float>> attributes(mesh.face_attributes.size());
  for (const Triangle& t : triangles) {
    for (Index v : t.v) {
      positions.push_back(mesh.positions[v]);
      normals.push_back(unit_or_up(face_normal_list[t.face]));
      if (!scene.face_colors.empty())
        colors.push_back(scene.face_colors[t.face]);
      else if (!scene.vertex_colors.empty())
        colors.push_back(scene.vertex_colors[v]);
      std::size_t a = 0;
      for (const auto& [name, values] : mesh.face_attributes)
        attributes[a++].push_back(static_cast<float>(values[t.face]));
    }
  }
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] = builder.positions(positions);
  primitive.attributes["NORMAL"] = builder.vectors(normals);
  if (!colors.empty()) primitive.attributes["COLOR_0"] = builder.vectors(colors);
  std::size_t a = 0;
  for (const auto& [name, values] : mesh.face_attributes)
    primitive.attributes[attribute_name(name)] =
        builder.floats(attributes[a++], TINYGLTF_TYPE_SCALAR);
  return primitive;
}

void add_line_set(const LineSet& set, ModelBuilder& builder) {
  std::vector<Eigen::Vector3d> points;
  std::vector<float> ids;
  std::vector<std::uint32_t> segments;
  for (std::size_t i = 0; i < set.polylines.size(); ++i) {
    const auto& line = set.polylines[i];
    for (std::size_t k = 0; k < line.size(); ++k) {
      if (k > 0) {
        segments.push_back(static_cast<std::uint32_t>(points.size() - 1));
        segments.push_back(static_cast<std::uint32_t>(points.size()));
      }
      points.push_back(line[k]);
      ids.push_back(static_cast<float>(i));
    }
  }
  if (segments.empty()) return;  // glTF accessors cannot be empty
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_LINE;
  primitive.attributes["POSITION"] = builder.positions(points);
  primitive.attributes["_ID"] = builder.floats(ids, TINYGLTF_TYPE_SCALAR);
  primitive.indices = builder.indices(segments);
  primitive.material = builder.material(set.name, set.color, false);
  builder.node(set.name, std::move(primitive));
}

void add_point_set(const PointSet& set, ModelBuilder& builder) {
  if (set.points.empty()) return;
  std::vector<float> ids(set.points.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<float>(i);
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_POINTS;
  primitive.attributes["POSITION"] = builder.positions(set.points);
  primitive.attributes["_ID"] = builder.floats(ids, TINYGLTF_TYPE_SCALAR);
  primitive.material = builder.material(set.name, set.color, false);
  builder.node(set.name, std::move(primitive));
}

}  // namespace

std::vector<std::uint8_t> write_glb(const Scene& scene) {
  check_sizes(scene);
  const BoundingBox box = bounding_box(scene.mesh);
  ModelBuilder builder(0.5 * (box.min + box.max));
  if (scene.mesh.face_count() > 0) {
    const bool split = !scene.mesh.face_attributes.empty() || !scene.face_colors.empty();
    tinygltf::Primitive primitive =
        split ? split_vertex_primitive(scene, builder) : shared_vertex_primitive(scene, builder);
    primitive.material = builder.material("surface", Color(0.8f, 0.8f, 0.8f), true);
    builder.node("surface", std::move(primitive));
  }
  for (const LineSet& set : scene.line_sets) add_line_set(set, builder);
  for (const PointSet& set : scene.point_sets) add_point_set(set, builder);
  builder.model().scenes[0].extras = to_value(scene.extras);

  std::ostringstream stream;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&builder.model(), stream, false, true))
    throw Error("write_glb: tinygltf could not serialize the scene");
  const std::string bytes = stream.str();
  return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
}

}  // namespace tessera
