// The one error hierarchy of Tessera.
//
// Error          something went wrong inside Tessera (CLI exit code 1)
//  InputError    the input is at fault (CLI exit code 2); the message says what, where, what to do
//   ParseError     a file or text that does not follow its format (line or byte offset)
//   TopologyError  a mesh whose connectivity Tessera cannot work on (non-manifold, non-orientable, ...)
//   GeometryError  coordinates Tessera cannot work on (NaN/Inf, all faces degenerate, ...)
//   LimitError     a resource limit was hit (names the limit and how to raise it)
//  CancelledError the user cancelled a running job
#pragma once

#include <stdexcept>
#include <string>

namespace tessera {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  // A short machine-readable name of the error class, e.g. "parse", "topology", "limit".
  virtual const char* kind() const noexcept { return "internal"; }
};

class InputError : public Error {
 public:
  using Error::Error;
  const char* kind() const noexcept override { return "input"; }
};

class ParseError : public InputError {
 public:
  using InputError::InputError;
  const char* kind() const noexcept override { return "parse"; }
};

class TopologyError : public InputError {
 public:
  using InputError::InputError;
  const char* kind() const noexcept override { return "topology"; }
};

class GeometryError : public InputError {
 public:
  using InputError::InputError;
  const char* kind() const noexcept override { return "geometry"; }
};

class LimitError : public InputError {
 public:
  using InputError::InputError;
  const char* kind() const noexcept override { return "limit"; }
};

class CancelledError : public Error {
 public:
  CancelledError() : Error("cancelled by the user") {}
  const char* kind() const noexcept override { return "cancelled"; }
};

}  // namespace tessera
