// Helpers for the mesh and I/O tests: bytes from text, temporary files, mesh comparison, and a
// small GLB/glTF assembler so that malformed glTF can be generated in the test itself, and meshes
// generated for the weld: parts side by side, a torus cracked along its seam.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "mesh/geometry.h"
#include "mesh/mesh.h"

namespace tessera::test {

inline std::vector<std::uint8_t> bytes_of(const std::string& text) {
  return std::vector<std::uint8_t>(text.begin(), text.end());
}

// A file under the test temporary folder, unique per test.
inline std::string temp_path(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "tessera_" + info->test_suite_name() + "_" + info->name() + "_" +
         name;
}

inline std::string write_temp_file(const std::string& name,
                                   const std::vector<std::uint8_t>& bytes) {
  const std::string path = temp_path(name);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  return path;
}

// Same vertex count, same faces, positions within `relative` x bounding-box diagonal.
inline void expect_same_mesh(const Mesh& a, const Mesh& b, double relative) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  ASSERT_EQ(a.face_count(), b.face_count());
  EXPECT_EQ(a.face_offsets, b.face_offsets);
  EXPECT_EQ(a.face_vertices, b.face_vertices);
  const double tolerance = relative * bounding_box(a).diagonal();
  for (std::size_t v = 0; v < a.vertex_count(); ++v)
    ASSERT_LE((a.positions[v] - b.positions[v]).norm(), tolerance) << "vertex " << v;
}

// `b` added to `a`, moved by `offset`.
inline Mesh joined(Mesh a, const Mesh& b, const Eigen::Vector3d& offset) {
  const Index first = static_cast<Index>(a.vertex_count());
  for (const Eigen::Vector3d& p : b.positions) a.add_vertex(p + offset);
  for (std::size_t f = 0; f < b.face_count(); ++f) {
    std::vector<Index> face(b.face(f).begin(), b.face(f).end());
    for (Index& v : face) v += first;
    a.add_face(face);
  }
  return a;
}

// A torus grid whose seam u = 2 pi has its own copy of the vertices at u = 0: cracked all around.
inline Mesh torus_cracked_at_seam(int major, int minor) {
  Mesh mesh;
  for (int i = 0; i <= major; ++i)
    for (int j = 0; j < minor; ++j) {
      const double u = 2 * M_PI * i / major, v = 2 * M_PI * j / minor;
      const double r = 1 + 0.3 * std::cos(v);
      mesh.add_vertex({r * std::cos(u), r * std::sin(u), 0.3 * std::sin(v)});
    }
  const auto at = [&](int i, int j) { return static_cast<Index>(i * minor + j % minor); };
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      mesh.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.add_face({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

template <class T>
void append_value(std::vector<std::uint8_t>& bytes, T value) {
  const std::size_t at = bytes.size();
  bytes.resize(at + sizeof(T));
  std::memcpy(bytes.data() + at, &value, sizeof(T));
}

template <class T>
void append_big_endian(std::vector<std::uint8_t>& bytes, T value) {
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  for (std::size_t i = sizeof(T); i-- > 0;) bytes.push_back(raw[i]);
}

// A GLB of the given JSON chunk and binary chunk (both padded as the format asks).
inline std::vector<std::uint8_t> make_glb(std::string json, std::vector<std::uint8_t> bin) {
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin.push_back(0);
  std::vector<std::uint8_t> glb;
  append_value<std::uint32_t>(glb, 0x46546C67);  // "glTF"
  append_value<std::uint32_t>(glb, 2);
  append_value<std::uint32_t>(glb,
                              static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  append_value<std::uint32_t>(glb, static_cast<std::uint32_t>(json.size()));
  append_value<std::uint32_t>(glb, 0x4E4F534A);  // "JSON"
  glb.insert(glb.end(), json.begin(), json.end());
  append_value<std::uint32_t>(glb, static_cast<std::uint32_t>(bin.size()));
  append_value<std::uint32_t>(glb, 0x004E4942);  // "BIN\0"
  glb.insert(glb.end(), bin.begin(), bin.end());
  return glb;
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = bytes[i] << 16 | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                            (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += kDigits[n >> 18 & 63];
    out += kDigits[n >> 12 & 63];
    out += i + 1 < bytes.size() ? kDigits[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

// The binary chunk of a unit right triangle: three float positions, then three uint32 indices.
inline std::vector<std::uint8_t> triangle_buffer() {
  std::vector<std::uint8_t> bin;
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) append_value(bin, x);
  for (std::uint32_t i : {0u, 1u, 2u}) append_value(bin, i);
  return bin;
}

// glTF JSON around triangle_buffer(); the accessor fields can be overridden to make it malformed.
inline std::string triangle_gltf_json(
    const std::string& buffer_uri_field,
    const std::string& position_accessor =
        R"("bufferView":0,"componentType":5126,"count":3,"type":"VEC3")",
    const std::string& nodes = R"([{"mesh":0}])") {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" + nodes +
         R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
         R"("accessors":[{)" +
         position_accessor +
         R"(},{"bufferView":1,"componentType":5125,"count":3,"type":"SCALAR"}],)"
         R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
         R"({"buffer":0,"byteOffset":36,"byteLength":12}],)"
         R"("buffers":[{"byteLength":48)" +
         buffer_uri_field + "}]}";
}

}  // namespace tessera::test
