#include "field/field_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string_view>

#include "base/text_scan.h"

namespace tessera {
namespace {

// The next line that is neither blank nor a '#' comment; false at the end of the text.
bool next_content_line(TextLines& lines, std::string_view& line) {
  while (lines.next(line)) {
    Tokens tokens(line);
    std::string_view first;
    if (tokens.next(first) && first[0] != '#') return true;
  }
  return false;
}

double read_number(TextLines& lines, Tokens& tokens, const char* what) {
  std::string_view token;
  if (!tokens.next(token)) lines.fail(std::string("missing ") + what);
  const std::optional<double> value = parse_double(token);
  if (!value) lines.fail(std::string("expected ") + what + ", got '" + std::string(token) + "'");
  if (!std::isfinite(*value)) lines.fail(std::string(what) + " is not finite");
  return *value;
}

std::size_t read_count(TextLines& lines, Tokens& tokens, const char* what) {
  std::string_view token;
  if (!tokens.next(token)) lines.fail(std::string("missing ") + what);
  const std::optional<std::int64_t> value = parse_integer(token);
  if (!value || *value < 0)
    lines.fail(std::string("expected ") + what + " (a non-negative integer), got '" +
               std::string(token) + "'");
  return static_cast<std::size_t>(*value);
}

Eigen::Vector3d read_vector(TextLines& lines, Tokens& tokens) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = read_number(lines, tokens, "a vector coordinate");
  return v;
}

void expect_line_end(TextLines& lines, Tokens& tokens, const std::string& expected) {
  std::string_view extra;
  if (tokens.next(extra)) lines.fail("unexpected '" + std::string(extra) + "' after " + expected);
}

bool ends_with_rawfield(const std::string& name) {
  constexpr std::string_view kExtension = ".rawfield";
  if (name.size() < kExtension.size()) return false;
  return std::equal(
      kExtension.begin(), kExtension.end(), name.end() - kExtension.size(),
      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

}  // namespace

std::vector<Eigen::Vector3d> read_rawfield(std::span<const std::uint8_t> bytes,
                                           const std::string& file_name, const Limits& limits) {
  TextLines lines(bytes, file_name);
  std::string_view line;
  if (!next_content_line(lines, line)) lines.fail("empty file; a .rawfield starts with 'N F'");
  Tokens header(line);
  const std::size_t n = read_count(lines, header, "the number of vectors per face N");
  const std::size_t faces = read_count(lines, header, "the face count F");
  expect_line_end(lines, header, "'N F'");
  if (n == 0) lines.fail("N is 0; a field needs at least one vector per face");
  check_limit(faces, limits.max_faces, "the field file's face count", "--max-faces");
  // Every face line holds at least 3N characters, so a short file cannot announce a huge F.
  if (faces > lines.remaining_bytes())
    lines.fail("announces " + std::to_string(faces) + " faces, more than the file can hold");
  std::vector<Eigen::Vector3d> directions;
  directions.reserve(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    if (!next_content_line(lines, line))
      lines.fail("ends after " + std::to_string(f) + " of " + std::to_string(faces) + " faces");
    Tokens tokens(line);
    directions.push_back(read_vector(lines, tokens));
    for (std::size_t k = 1; k < n; ++k) read_vector(lines, tokens);
    expect_line_end(lines, tokens,
                    std::to_string(n) + " vectors (" + std::to_string(3 * n) + " numbers)");
  }
  if (next_content_line(lines, line))
    lines.fail("more face lines than the " + std::to_string(faces) + " the header announces");
  return directions;
}

std::vector<Eigen::Vector3d> read_face_directions(std::span<const std::uint8_t> bytes,
                                                  const std::string& file_name,
                                                  const Limits& limits) {
  TextLines lines(bytes, file_name);
  std::vector<Eigen::Vector3d> directions;
  std::string_view line;
  while (next_content_line(lines, line)) {
    check_limit(directions.size() + 1, limits.max_faces, "the field file's face count",
                "--max-faces");
    Tokens tokens(line);
    directions.push_back(read_vector(lines, tokens));
    expect_line_end(lines, tokens, "'x y z'");
  }
  if (directions.empty()) lines.fail("no face directions; expected one line 'x y z' per face");
  return directions;
}

std::vector<Eigen::Vector3d> read_field(std::span<const std::uint8_t> bytes,
                                        const std::string& file_name, const Limits& limits) {
  return ends_with_rawfield(file_name) ? read_rawfield(bytes, file_name, limits)
                                       : read_face_directions(bytes, file_name, limits);
}

}  // namespace tessera
