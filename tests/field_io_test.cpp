// Cross-field files: .rawfield and per-face directions, and their errors (core/field/field_io).
#include <gtest/gtest.h>

#include <string>

#include "base/error.h"
#include "field/field_io.h"
#include "mesh_test_util.h"

namespace tessera {
namespace {

using test::bytes_of;

std::vector<Eigen::Vector3d> raw(const std::string& text) {
  const auto bytes = bytes_of(text);
  return read_rawfield(bytes, "f.rawfield", Limits());
}

// The ParseError's message, or "" if the text parses.
std::string raw_error(const std::string& text) {
  try {
    raw(text);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

TEST(FieldIo, ReadsRawfieldFirstVectorPerFace) {
  const auto d = raw("4 2\n1 0 0 0 1 0 -1 0 0 0 -1 0\n0 0 1 1 0 0 0 0 -1 -1 0 0 \r\n");
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0], Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(d[1], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(raw("1 1\n0.5 -2e-3 +3\n")[0], Eigen::Vector3d(0.5, -2e-3, 3));
}

TEST(FieldIo, RawfieldErrorsNameTheLine) {
  EXPECT_NE(raw_error("").find("empty"), std::string::npos);
  EXPECT_NE(raw_error("4\n").find(":1:"), std::string::npos);
  EXPECT_NE(raw_error("four 1\n").find("'four'"), std::string::npos);
  EXPECT_NE(raw_error("0 1\n\n").find("N is 0"), std::string::npos);
  EXPECT_NE(raw_error("1 2\n1 0 0\n").find("ends after 1 of 2"), std::string::npos);
  EXPECT_NE(raw_error("1 1\n1 0 x\n").find("f.rawfield:2: expected a vector coordinate, got 'x'"),
            std::string::npos);
  EXPECT_NE(raw_error("2 1\n1 0 0 0 1\n").find(":2: missing"), std::string::npos);
  EXPECT_NE(raw_error("1 1\n1 0 0 7\n").find("unexpected '7'"), std::string::npos);
  EXPECT_NE(raw_error("1 1\n1 0 0\n0 1 0\n").find(":3: more face lines"), std::string::npos);
  EXPECT_NE(raw_error("1 1\n1 nan 0\n").find("not finite"), std::string::npos);
  EXPECT_NE(raw_error("1 100\n1 0 0\n").find("more than the file can hold"), std::string::npos);
  EXPECT_NE(raw_error(std::string("1 1\n1 0\0 0\n", 12)).find("NUL"), std::string::npos);
}

TEST(FieldIo, NeverReadsPastTheBuffer) {
  // The bytes after the span would complete the file; the reader must not see them.
  const std::string text = "1 1\n1 0 0\n";
  const auto bytes = bytes_of(text);
  const std::span<const std::uint8_t> cut(bytes.data(), text.size() - 3);  // "1 1\n1 0"
  EXPECT_THROW(read_rawfield(cut, "f.rawfield", Limits()), ParseError);
}

TEST(FieldIo, RawfieldFaceCountIsLimited) {
  Limits limits;
  limits.max_faces = 1;
  const auto bytes = bytes_of("1 2\n1 0 0\n1 0 0\n");
  EXPECT_THROW(read_rawfield(bytes, "f.rawfield", limits), LimitError);
}

TEST(FieldIo, ReadsPerFaceDirections) {
  const auto bytes = bytes_of("# one direction per face\n1 0 0\n\n  0 1 0\n");
  const auto d = read_face_directions(bytes, "f.txt", Limits());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[1], Eigen::Vector3d(0, 1, 0));
  EXPECT_THROW(read_face_directions(bytes_of("1 0\n"), "f.txt", Limits()), ParseError);
  EXPECT_THROW(read_face_directions(bytes_of("# nothing\n"), "f.txt", Limits()), ParseError);
}

TEST(FieldIo, PicksTheFormatByExtension) {
  const auto bytes = bytes_of("1 1\n1 0 0\n");
  EXPECT_EQ(read_field(bytes, "dir/F.RAWFIELD", Limits()).size(), 1u);
  // The same text as per-face directions: two faces, the first "1 1" is not a 3D vector.
  EXPECT_THROW(read_field(bytes, "f.txt", Limits()), ParseError);
}

}  // namespace
}  // namespace tessera
