#include "base/text_scan.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "base/error.h"

namespace tessera {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view strip_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+')
    token.remove_prefix(1);
  return token;
}

// strtod needs a NUL-terminated copy; tokens longer than any sensible number are refused.
std::optional<double> parse_double_strtod(std::string_view token) {
  char buffer[128];
  if (token.empty() || token.size() >= sizeof buffer) return std::nullopt;
  std::memcpy(buffer, token.data(), token.size());
  buffer[token.size()] = '\0';
  if (buffer[0] == ' ' || buffer[0] == '\t') return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(buffer, &end);
  if (end != buffer + token.size()) return std::nullopt;
  // Hexadecimal floats are no mesh format's syntax.
  if (std::memchr(buffer, 'x', token.size()) || std::memchr(buffer, 'X', token.size()))
    return std::nullopt;
  return value;
}

}  // namespace

bool TextLines::next(std::string_view& line) {
  if (position_ >= text_.size()) return false;
  const std::size_t end = text_.find('\n', position_);
  const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
  line = text_.substr(position_, stop - position_);
  position_ = end == std::string_view::npos ? text_.size() : end + 1;
  ++line_number_;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.find('\0') != std::string_view::npos)
    fail("binary data (a NUL byte) in a text file; is this file in another format?");
  return true;
}

void TextLines::fail(const std::string& message) const {
  throw ParseError(file_name_ + ":" + std::to_string(line_number_) + ": " + message);
}

bool Tokens::next(std::string_view& token) {
  std::size_t i = 0;
  while (i < rest_.size() && is_space(rest_[i])) ++i;
  std::size_t j = i;
  while (j < rest_.size() && !is_space(rest_[j])) ++j;
  token = rest_.substr(i, j - i);
  rest_.remove_prefix(j);
  return !token.empty();
}

std::optional<double> parse_double(std::string_view token) {
  token = strip_plus(token);
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  double value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error == std::errc() && end == token.data() + token.size()) return value;
  if (error != std::errc::result_out_of_range) return std::nullopt;
    // from_chars leaves the value alone on overflow and underflow; strtod tells them apart.
#endif
  return parse_double_strtod(token);
}

std::optional<std::int64_t> parse_integer(std::string_view token) {
  token = strip_plus(token);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

std::string quoted(std::string_view token) {
  std::string text;
  text.reserve(token.size() + 2);
  text.append(1, '\'').append(token).append(1, '\'');
  return text;
}

bool is_blank(std::span<const std::uint8_t> bytes) {
  for (std::uint8_t b : bytes)
    if (!is_space(static_cast<char>(b)) && b != '\n') return false;
  return true;
}

void throw_non_finite_position(std::size_t vertex, const std::string& where) {
  throw GeometryError(where + ": vertex " + std::to_string(vertex) +
                      " has a non-finite coordinate (NaN or infinity); fix or remove it in the "
                      "program that wrote the file");
}

}  // namespace tessera
