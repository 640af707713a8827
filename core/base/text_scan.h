// Scanning text formats (the mesh formats OBJ, OFF, ASCII PLY, ASCII STL; field files; CPLEX LP)
// straight from a byte buffer: no NUL termination is assumed and nothing is read past the buffer's
// end. Numbers are parsed with std::from_chars where the standard library has it for floating point
// (glibc builds), and with a bounded strtod otherwise (Emscripten's libc++ lacks it), so one code
// path serves both builds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tessera {

// Lines of a text buffer, without their "\n" or "\r\n". Throws ParseError on a NUL byte: the file
// is binary, not the text format its name promises.
class TextLines {
 public:
  TextLines(std::span<const std::uint8_t> bytes, std::string file_name)
      : text_(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
        file_name_(std::move(file_name)) {}

  bool next(std::string_view& line);
  std::size_t line_number() const { return line_number_; }  // of the line last returned, from 1
  std::size_t offset() const { return position_; }          // bytes consumed so far
  std::size_t remaining_bytes() const { return text_.size() - position_; }
  const std::string& file_name() const { return file_name_; }

  // "<file>:<line>: <message>"
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::string_view text_;
  std::string file_name_;
  std::size_t position_ = 0;
  std::size_t line_number_ = 0;
};

// Whitespace-separated tokens of one line.
class Tokens {
 public:
  explicit Tokens(std::string_view line) : rest_(line) {}
  bool next(std::string_view& token);
  std::string_view rest() const { return rest_; }

 private:
  std::string_view rest_;
};

// A whole token as a number; nullopt if it is not one. Overflow gives +-infinity (rejected later as
// a non-finite coordinate), underflow gives 0; a leading '+' is accepted.
std::optional<double> parse_double(std::string_view token);
std::optional<std::int64_t> parse_integer(std::string_view token);

// The token in single quotes, for messages.
std::string quoted(std::string_view token);

// True if the buffer holds nothing but whitespace.
bool is_blank(std::span<const std::uint8_t> bytes);

// Throws GeometryError "<where>: vertex <v> has a non-finite coordinate ..."; callers test
// p.allFinite() first, so that the message is only built when needed.
[[noreturn]] void throw_non_finite_position(std::size_t vertex, const std::string& where);

}  // namespace tessera
