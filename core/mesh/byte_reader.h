// Bounds-checked reading of little- or big-endian binary data (binary PLY, binary STL): every read
// checks the remaining bytes first and reports truncation with the byte offset.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "base/error.h"

namespace tessera {

class ByteReader {
 public:
  ByteReader(std::span<const std::uint8_t> bytes, std::size_t offset, bool big_endian,
             std::string file_name)
      : bytes_(bytes), offset_(offset), big_endian_(big_endian), file_name_(std::move(file_name)) {}

  std::size_t offset() const { return offset_; }
  std::size_t remaining() const { return bytes_.size() - offset_; }

  // Throws ParseError unless n more bytes are there; `what` says what was being read.
  void require(std::uint64_t n, std::string_view what) const {
    if (n > remaining())
      fail("the file ends in the middle of " + std::string(what) + " (" + std::to_string(n) +
           " bytes needed, " + std::to_string(remaining()) + " left); it is truncated");
  }

  template <class T>
  T read(std::string_view what) {
    require(sizeof(T), what);
    std::uint8_t raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    if (big_endian_ != (std::endian::native == std::endian::big)) reverse(raw, sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  void skip(std::uint64_t n, std::string_view what) {
    require(n, what);
    offset_ += static_cast<std::size_t>(n);
  }

  // "<file>: byte <offset>: <message>"
  [[noreturn]] void fail(const std::string& message) const {
    throw ParseError(file_name_ + ": byte " + std::to_string(offset_) + ": " + message);
  }

 private:
  static void reverse(std::uint8_t* raw, std::size_t n) {
    for (std::size_t i = 0; i < n / 2; ++i) std::swap(raw[i], raw[n - 1 - i]);
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t offset_;
  bool big_endian_;
  std::string file_name_;
};

}  // namespace tessera
