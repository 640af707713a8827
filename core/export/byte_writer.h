// Appending numbers and text to a byte buffer: little-endian binary values (PLY, STL) and doubles
// as short text that reads back exactly (OBJ, OFF, ASCII PLY).
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

namespace tessera {

class ByteWriter {
 public:
  template <class T>
  void put(T value) {  // little-endian, as every supported host is (x86, arm, wasm)
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }
  void text(std::string_view s);
  // The shortest of 15 or 17 significant digits that reads back as the same double.
  void number(double x);
  void integer(long long x);

  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace tessera
