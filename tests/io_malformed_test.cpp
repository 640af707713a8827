// Every class of bad input, generated here, must give a typed error whose message names the file
// and the place (line, byte offset, element) - never a crash, a hang or an allocation of what a
// header merely announces.
#include <gtest/gtest.h>

#include <chrono>

#include "base/error.h"
#include "export/writers.h"
#include "mesh/load.h"
#include "mesh/shapes.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::bytes_of;

// Reads (and validates) the bytes expecting error type E with every one of `parts` in its message.
template <class E>
void expect_error(const std::vector<std::uint8_t>& bytes, const std::string& name,
                  std::initializer_list<std::string> parts, const Limits& limits = {}) {
  const auto start = std::chrono::steady_clock::now();
  try {
    load_mesh(bytes, name, limits);
    ADD_FAILURE() << name << ": expected an error";
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    for (const std::string& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "'" << part << "' not in: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << name << ": wrong error type: " << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST(Malformed, EmptyAndBlankFiles) {
  for (const char* name : {"e.obj", "e.off", "e.ply", "e.stl", "e.glb", "e.gltf"}) {
    expect_error<ParseError>({}, name, {"empty"});
    expect_error<ParseError>(bytes_of(" \n\t\r\n  "), name, {"whitespace"});
  }
}

TEST(Malformed, ObjIndicesOutOfRange) {
  expect_error<ParseError>(bytes_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"), "i.obj",
                           {":4:", "vertex index 4", "only 3 vertices"});
  expect_error<ParseError>(bytes_of("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n"), "r.obj",
                           {":3:", "relative vertex index -3"});
  expect_error<ParseError>(bytes_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "z.obj",
                           {":4:", "index 0"});
}

TEST(Malformed, ObjSyntax) {
  expect_error<ParseError>(bytes_of("v 0 0 0\nv 1 zero 0\n"), "n.obj",
                           {":2:", "'zero' is not a number"});
  expect_error<ParseError>(bytes_of("v 0 0\n"), "s.obj", {":1:", "three coordinates"});
  expect_error<ParseError>(bytes_of("v 0 0 0\nv 1 0 0\nf 1 2\n"), "f.obj",
                           {":3:", "at least three"});
  expect_error<ParseError>(bytes_of(std::string("v 0 0 0\n\0\x01\x02", 11)), "b.obj",
                           {":2:", "binary data"});
}

TEST(Malformed, NonFiniteCoordinates) {
  expect_error<GeometryError>(bytes_of("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"), "nan.obj",
                              {":2:", "vertex 1", "non-finite"});
  expect_error<GeometryError>(bytes_of("OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n"), "inf.off",
                              {":5:", "vertex 2"});
  expect_error<GeometryError>(bytes_of("v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"), "big.obj",
                              {"vertex 1"});
}

TEST(Malformed, OffCountsAndIndices) {
  expect_error<LimitError>(bytes_of("OFF\n3 10000000000 0\n0 0 0\n"), "huge.off",
                           {"10000000000", "--max-faces"});
  expect_error<ParseError>(bytes_of("OFF\n1000 1 0\n0 0 0\n"), "short.off",
                           {"announces 1000 vertices", "truncated"});
  expect_error<ParseError>(bytes_of("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "idx.off",
                           {":6:", "vertex '3'"});
  expect_error<ParseError>(
      bytes_of("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# a comment, no second face\n"),
      "end.off", {"1 of 2 faces", "truncated"});
  expect_error<ParseError>(bytes_of("NOT\n3 1 0\n"), "key.off", {":1:", "keyword OFF"});
}

std::string ply_header(const std::string& format, std::uint64_t vertices, std::uint64_t faces) {
  return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(Malformed, PlyTruncatedBinary) {
  const std::vector<std::uint8_t> full = write_ply(icosphere(1));
  const std::vector<std::uint8_t> cut(full.begin(), full.begin() + full.size() - 7);
  expect_error<ParseError>(cut, "cut.ply", {"byte", "truncated"});
}

TEST(Malformed, PlyAbsurdAndInconsistentCounts) {
  expect_error<LimitError>(bytes_of(ply_header("binary_little_endian", 3, 10'000'000'000)),
                           "huge.ply", {"10000000000", "--max-faces"});
  expect_error<ParseError>(bytes_of(ply_header("binary_little_endian", 1'000'000, 1) + "0123"),
                           "lie.ply", {"1000000 vertex elements", "truncated"});
  expect_error<ParseError>(bytes_of(ply_header("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"),
                           "idx.ply", {":13:", "face 0 refers to vertex 9"});
  expect_error<ParseError>(bytes_of("ply\nformat ascii 1.0\nelement vertex 1\n"), "open.ply",
                           {"end_header"});
  expect_error<ParseError>(bytes_of(ply_header("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
                           "two.ply", {":13:", "2 corners"});
}

TEST(Malformed, StlTruncatedAndAbsurd) {
  std::vector<std::uint8_t> stl = write_stl(icosphere(1));
  stl.resize(stl.size() - 30);
  expect_error<ParseError>(stl, "cut.stl", {"byte 84", "announces 80 triangles", "truncated"});
  std::vector<std::uint8_t> huge(84, 0);
  huge[80] = huge[81] = huge[82] = huge[83] = 0xFF;
  expect_error<LimitError>(huge, "huge.stl", {"4294967295", "--max-faces"});
  expect_error<ParseError>(
      bytes_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
               "endloop\nendfacet\nendsolid\n"),
      "two.stl", {":7:", "exactly 3 vertices"});
}

TEST(Malformed, GlbAccessorsOutsideTheirBuffers) {
  const std::string no_uri;
  expect_error<ParseError>(
      test::make_glb(
          test::triangle_gltf_json(
              no_uri, R"("bufferView":0,"componentType":5126,"count":300,"type":"VEC3")"),
          test::triangle_buffer()),
      "count.glb", {"mesh 0 primitive 0 POSITION", "300 elements reach past"});
  expect_error<ParseError>(
      test::make_glb(
          test::triangle_gltf_json(
              no_uri,
              R"("bufferView":0,"byteOffset":30,"componentType":5126,"count":3,"type":"VEC3")"),
          test::triangle_buffer()),
      "offset.glb", {"reach past"});
  expect_error<ParseError>(
      test::make_glb(test::triangle_gltf_json(
                         no_uri, R"("bufferView":7,"componentType":5126,"count":3,"type":"VEC3")"),
                     test::triangle_buffer()),
      "view.glb", {"bufferView"});
  // An index beyond the primitive's vertices.
  std::vector<std::uint8_t> bin = test::triangle_buffer();
  bin[36 + 8] = 9;
  expect_error<ParseError>(test::make_glb(test::triangle_gltf_json(no_uri), bin), "index.glb",
                           {"index 2 is 9", "3 vertices"});
}

TEST(Malformed, GlbStructure) {
  const std::vector<std::uint8_t> glb =
      test::make_glb(test::triangle_gltf_json(""), test::triangle_buffer());
  EXPECT_EQ(load_mesh(glb, "ok.glb").mesh.face_count(), 1u);  // the base of the broken variants
  const std::vector<std::uint8_t> cut(glb.begin(), glb.begin() + glb.size() / 2);
  expect_error<ParseError>(cut, "cut.glb", {"not a valid GLB"});
  expect_error<ParseError>(
      test::make_glb(test::triangle_gltf_json(
                         "", R"("bufferView":0,"componentType":5126,"count":3,"type":"VEC3")",
                         R"([{"mesh":0,"children":[1]},{"children":[0]}])"),
                     test::triangle_buffer()),
      "cycle.glb", {"node 0 is reached twice"});
  expect_error<ParseError>(bytes_of("{\"asset\": {\"version\": \"2.0\"}, \"buffers\": ["),
                           "bad.gltf", {"not a valid glTF"});
  // From memory, an external buffer is refused rather than looked up on disk.
  expect_error<ParseError>(bytes_of(test::triangle_gltf_json(R"(,"uri":"triangle.bin")")),
                           "ext.gltf", {"not a valid glTF"});
}

TEST(Malformed, TopologyErrorsNameTheFileAndThePlace) {
  expect_error<TopologyError>(
      bytes_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"),
      "fin.obj", {"non-manifold edge 0-1", "3 faces"});
  expect_error<TopologyError>(
      bytes_of("v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n"), "bowtie.obj",
      {"non-manifold vertex 0"});
  expect_error<TopologyError>(bytes_of("v 0 0 0\n"), "cloud.obj", {"no faces"});
}

TEST(Malformed, UnknownFormatAndLimits) {
  expect_error<ParseError>(bytes_of("hello world\n"), "mystery.dat",
                           {"cannot tell the mesh format"});
  Limits small;
  small.max_vertices = 10;
  expect_error<LimitError>(write_obj(icosphere(1)), "many.obj", {"--max-vertices"}, small);
  small = {};
  small.max_file_bytes = 100;
  expect_error<LimitError>(write_obj(icosphere(1)), "large.obj", {"--max-file-bytes"}, small);
}

}  // namespace
}  // namespace tessera
