#include <gtest/gtest.h>

#include "base/error.h"
#include "export/glb.h"
#include "export/write_mesh.h"
#include "export/writers.h"
#include "mesh/readers.h"
#include "mesh/shapes.h"
#include "mesh/tinygltf.h"
#include "mesh/validate.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::bytes_of;
using test::expect_same_mesh;

const Limits kLimits;

Mesh torus_with_attributes() {
  Mesh mesh = quad_torus(2.0, 0.5, 12, 6);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    mesh.face_attributes["patch"].push_back(static_cast<std::int32_t>(f % 5));
    mesh.face_attributes["tile"].push_back(-static_cast<std::int32_t>(f));
  }
  return mesh;
}

TEST(RoundTrip, ObjKeepsPolygonsAndExactPositions) {
  const Mesh mesh = quad_torus(2.0, 0.5, 12, 6);
  expect_same_mesh(mesh, read_obj(write_obj(mesh), "t.obj", kLimits), 0.0);
  const Mesh triangles = icosphere(2, 3.7);
  expect_same_mesh(triangles, read_obj(write_obj(triangles), "s.obj", kLimits), 0.0);
}

TEST(RoundTrip, OffKeepsPolygonsAndExactPositions) {
  const Mesh mesh = quad_torus(2.0, 0.5, 12, 6);
  expect_same_mesh(mesh, read_off(write_off(mesh), "t.off", kLimits), 0.0);
}

TEST(RoundTrip, PlyBinaryAndAsciiKeepFaceAttributes) {
  const Mesh mesh = torus_with_attributes();
  for (bool binary : {true, false}) {
    const Mesh back = read_ply(write_ply(mesh, binary), "t.ply", kLimits);
    expect_same_mesh(mesh, back, 0.0);
    EXPECT_EQ(back.face_attributes, mesh.face_attributes) << (binary ? "binary" : "ascii");
  }
}

TEST(RoundTrip, StlKeepsTrianglesWithinFloatPrecision) {
  const Mesh mesh = icosphere(2);
  const Mesh back = read_stl(write_stl(mesh), "s.stl", kLimits);
  ASSERT_EQ(back.vertex_count(), mesh.vertex_count());  // shared vertices welded again
  ASSERT_EQ(back.face_count(), mesh.face_count());
  for (std::size_t c = 0; c < mesh.corner_count(); ++c)
    EXPECT_LE(
        (back.positions[back.face_vertices[c]] - mesh.positions[mesh.face_vertices[c]]).norm(),
        1e-6);
  // Quads become two triangles each.
  const Mesh quads = quad_torus(1, 0.3, 8, 4);
  EXPECT_EQ(read_stl(write_stl(quads), "q.stl", kLimits).face_count(), 2 * quads.face_count());
}

TEST(RoundTrip, GlbKeepsVerticesFacesAndPositions) {
  Mesh mesh = double_torus(2);
  for (auto& p : mesh.positions) p += Eigen::Vector3d(1000, -2000, 3000);  // far from the origin
  const Mesh back = read_gltf(encode_mesh(mesh, "d.glb"), "d.glb", kLimits);
  expect_same_mesh(mesh, back, 1e-6);
}

TEST(RoundTrip, GlbWithFaceAttributesSplitsVerticesThatReadBackWelded) {
  const Mesh mesh = torus_with_attributes();
  Scene scene;
  scene.mesh = mesh;
  const auto glb = write_glb(scene);
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromMemory(&model, &error, &warning, glb.data(),
                                                        static_cast<unsigned>(glb.size())));
  const auto& attributes = model.meshes[0].primitives[0].attributes;
  ASSERT_TRUE(attributes.count("_PATCH"));
  ASSERT_TRUE(attributes.count("_TILE"));
  EXPECT_EQ(model.accessors[attributes.at("_PATCH")].count, 3 * 2 * mesh.face_count());
  const Mesh back = read_gltf(glb, "t.glb", kLimits);
  EXPECT_EQ(back.vertex_count(), mesh.vertex_count());
  EXPECT_EQ(back.face_count(), 2 * mesh.face_count());
}

TEST(RoundTrip, GlbCarriesLinesPointsColoursAndExtras) {
  Scene scene;
  scene.mesh = icosphere(1);
  scene.face_colors.assign(scene.mesh.face_count(), Color(0.2f, 0.4f, 0.6f));
  scene.line_sets.push_back(
      {"arcs", {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 1}, {0, 0, 2}}}, Color(0, 0, 0)});
  scene.point_sets.push_back({"singularities", {{0, 0, 1}, {0, 0, -1}}, Color(1, 0, 0)});
  scene.extras = {{"patches", 12}, {"objective", 3.5}, {"name", "test"}, {"list", {1, 2}}};
  const auto glb = write_glb(scene);
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromMemory(&model, &error, &warning, glb.data(),
                                                        static_cast<unsigned>(glb.size())))
      << error;
  ASSERT_EQ(model.nodes.size(), 3u);
  EXPECT_EQ(model.nodes[1].name, "arcs");
  const auto& lines = model.meshes[1].primitives[0];
  EXPECT_EQ(lines.mode, TINYGLTF_MODE_LINE);
  EXPECT_EQ(model.accessors[lines.indices].count, 2u * 3);  // 2 + 1 segments
  EXPECT_EQ(model.meshes[2].primitives[0].mode, TINYGLTF_MODE_POINTS);
  EXPECT_TRUE(model.meshes[0].primitives[0].attributes.count("COLOR_0"));
  const tinygltf::Value& extras = model.scenes[0].extras;
  EXPECT_EQ(extras.Get("patches").GetNumberAsInt(), 12);
  EXPECT_DOUBLE_EQ(extras.Get("objective").GetNumberAsDouble(), 3.5);
  EXPECT_EQ(extras.Get("name").Get<std::string>(), "test");
  EXPECT_EQ(extras.Get("list").ArrayLen(), 2u);
  // The surface reads back without the lines and points.
  EXPECT_EQ(read_gltf(glb, "s.glb", kLimits).face_count(), scene.mesh.face_count());
}

TEST(RoundTrip, WriteMeshPicksTheFormatByExtension) {
  const Mesh mesh = torus(1, 0.3, 10, 5);
  for (const char* name : {"a.obj", "a.OFF", "a.ply", "a.stl", "a.glb"}) {
    Mesh back = read_mesh(encode_mesh(mesh, name), name, kLimits);
    validate_mesh(back);
    EXPECT_EQ(back.vertex_count(), mesh.vertex_count()) << name;
    EXPECT_EQ(back.face_count(), mesh.face_count()) << name;
  }
  EXPECT_THROW(encode_mesh(mesh, "a.xyz"), InputError);
}

TEST(ReadObj, AcceptsAllCornerFormsNegativeIndicesAndIgnoredStatements) {
  const std::string text =
      "# comment\r\nmtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0 1.0\nv 1 1 0 0.5 0.5 0.5\nv +0 1 0\n"
      "vt 0 0\nvt 1 0\nvn 0 0 1\ng group\ns off\nusemtl red\n"
      "f 1/1/1 2/2/1 3//1\nf -4 -2 -1\nl 1 2\np 3\nvp 0.5\n";
  const Mesh mesh = read_obj(bytes_of(text), "forms.obj", kLimits);
  ASSERT_EQ(mesh.vertex_count(), 4u);
  ASSERT_EQ(mesh.face_count(), 2u);
  EXPECT_EQ(std::vector<Index>(mesh.face(1).begin(), mesh.face(1).end()),
            (std::vector<Index>{0, 2, 3}));
  EXPECT_EQ(mesh.positions[3], Eigen::Vector3d(0, 1, 0));
}

TEST(ReadObj, AcceptsForwardReferencesAndPolygons) {
  const Mesh mesh =
      read_obj(bytes_of("f 1 2 3 4\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"), "f.obj", kLimits);
  EXPECT_EQ(mesh.face_size(0), 4u);
}

TEST(ReadOff, AcceptsVariantsCommentsAndCountsOnTheKeywordLine) {
  const std::string text =
      "COFF 4 2 0\n# a comment\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n\n1 1 0 0 0 255 255\n"
      "0 1 0 9 9 9 9\n3 0 1 2 10 20 30\n3 0 2 3  # trailing comment\n";
  const Mesh mesh = read_off(bytes_of(text), "c.off", kLimits);
  EXPECT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.face_count(), 2u);
  EXPECT_EQ(mesh.positions[2], Eigen::Vector3d(1, 1, 0));
}

TEST(ReadPly, ReadsBigEndianAndSkipsExtraPropertiesAndElements) {
  std::string header =
      "ply\nformat binary_big_endian 1.0\ncomment made in a test\nelement vertex 3\n"
      "property float x\nproperty uchar red\nproperty double y\nproperty float z\n"
      "property list uchar float extra\nelement face 1\nproperty int flags\n"
      "property list uchar uint vertex_indices\nproperty short region\n"
      "element edge 1\nproperty int v1\nproperty int v2\nend_header\n";
  std::vector<std::uint8_t> bytes = bytes_of(header);
  const float xs[3] = {0, 1, 0}, zs[3] = {0, 0, 2};
  const double ys[3] = {0, 0, 1};
  for (int v = 0; v < 3; ++v) {
    test::append_big_endian<float>(bytes, xs[v]);
    bytes.push_back(200);
    test::append_big_endian<double>(bytes, ys[v]);
    test::append_big_endian<float>(bytes, zs[v]);
    bytes.push_back(2);
    test::append_big_endian<float>(bytes, 0.5f);
    test::append_big_endian<float>(bytes, 0.25f);
  }
  test::append_big_endian<std::int32_t>(bytes, 99);
  bytes.push_back(3);
  for (std::uint32_t i : {0u, 1u, 2u}) test::append_big_endian(bytes, i);
  test::append_big_endian<std::int16_t>(bytes, -7);
  test::append_big_endian<std::int32_t>(bytes, 0);
  test::append_big_endian<std::int32_t>(bytes, 1);
  const Mesh mesh = read_ply(bytes, "be.ply", kLimits);
  ASSERT_EQ(mesh.vertex_count(), 3u);
  EXPECT_EQ(mesh.positions[2], Eigen::Vector3d(0, 1, 2));
  ASSERT_EQ(mesh.face_count(), 1u);
  EXPECT_EQ(mesh.face_attributes.at("region"), std::vector<std::int32_t>{-7});
  EXPECT_EQ(mesh.face_attributes.at("flags"), std::vector<std::int32_t>{99});
}

TEST(ReadStl, ReadsAsciiAndWeldsSharedCorners) {
  const std::string text =
      "solid square\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
      "endloop\nendfacet\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 1 0\n"
      "  vertex 0 1 0\n endloop\nendfacet\nendsolid square\n";
  const Mesh mesh = read_stl(bytes_of(text), "a.stl", kLimits);
  EXPECT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.face_count(), 2u);
}

TEST(ReadStl, BinaryStartingWithSolidIsStillBinary) {
  std::vector<std::uint8_t> bytes = write_stl(icosphere(0));
  std::memcpy(bytes.data(), "solid but binary", 16);
  EXPECT_EQ(read_stl(bytes, "b.stl", kLimits).face_count(), 20u);
}

TEST(ReadGltf, EmbeddedBufferWithNodeTransforms) {
  // The triangle under a parent that translates and a child that scales by -1 in x (mirroring).
  const std::string nodes =
      R"([{"children":[1],"translation":[10,0,0]},{"mesh":0,"scale":[-1,2,1]}])";
  const std::string json = test::triangle_gltf_json(
      R"(,"uri":"data:application/octet-stream;base64,)" + test::base64(test::triangle_buffer()) +
          "\"",
      R"("bufferView":0,"componentType":5126,"count":3,"type":"VEC3")", nodes);
  const Mesh mesh = read_gltf(bytes_of(json), "t.gltf", kLimits);
  ASSERT_EQ(mesh.vertex_count(), 3u);
  EXPECT_EQ(mesh.positions[1], Eigen::Vector3d(9, 0, 0));
  EXPECT_EQ(mesh.positions[2], Eigen::Vector3d(10, 2, 0));
  // Mirrored, the winding is reversed so that the normal keeps pointing the same way as drawn.
  EXPECT_EQ(std::vector<Index>(mesh.face(0).begin(), mesh.face(0).end()),
            (std::vector<Index>{0, 2, 1}));
}

TEST(ReadGltf, ExternalBufferBesideTheFileWhenReadFromAPath) {
  test::write_temp_file("triangle.bin", test::triangle_buffer());
  const std::string bin_name = test::temp_path("triangle.bin").substr(::testing::TempDir().size());
  const std::string path = test::write_temp_file(
      "t.gltf", bytes_of(test::triangle_gltf_json(R"(,"uri":")" + bin_name + "\"")));
  const Mesh mesh = read_mesh_file(path, kLimits);
  EXPECT_EQ(mesh.face_count(), 1u);
  EXPECT_EQ(mesh.positions[2], Eigen::Vector3d(0, 1, 0));
}

TEST(ReadGltf, TriangleStripsAndNonIndexedPrimitives) {
  std::vector<std::uint8_t> bin;
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 0.f})
    test::append_value(bin, x);
  const std::string json =
      R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":5},{"attributes":{"POSITION":0},"mode":1}]}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":48}],"buffers":[{"byteLength":48}]})";
  const Mesh mesh = read_gltf(test::make_glb(json, bin), "strip.glb", kLimits);
  EXPECT_EQ(mesh.face_count(), 2u);  // the strip; the line primitive is not surface
  EXPECT_EQ(mesh.vertex_count(), 4u);
}

TEST(ReadMesh, SniffsTheFormatWhenTheNameDoesNotTell) {
  EXPECT_EQ(detect_mesh_format(write_ply(icosphere(0)), "upload"), MeshFormat::ply);
  EXPECT_EQ(detect_mesh_format(write_stl(icosphere(0)), "upload"), MeshFormat::stl);
  EXPECT_EQ(detect_mesh_format(write_off(icosphere(0)), "upload"), MeshFormat::off);
  EXPECT_EQ(detect_mesh_format(write_obj(icosphere(0)), "upload"), MeshFormat::obj);
  EXPECT_EQ(detect_mesh_format(encode_mesh(icosphere(0), "x.glb"), "upload"), MeshFormat::gltf);
  EXPECT_EQ(read_mesh(write_obj(icosphere(0)), "upload.bin", kLimits).face_count(), 20u);
}

}  // namespace
}  // namespace tessera
