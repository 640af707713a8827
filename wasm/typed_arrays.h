// Conversions between JS values and C++ containers at the binding boundary: typed arrays are
// copied once in each direction (the wasm heap may move when it grows), JSON goes through
// JSON.stringify/parse so that nlohmann::json is the one JSON type of the core.
#pragma once

#include <emscripten/val.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/error.h"

namespace tessera::wasm {

// A JS typed array (or plain array) of numbers as a vector; throws InputError naming `what` if the
// value is not array-like.
template <class T>
std::vector<T> from_typed_array(const emscripten::val& array, const char* what) {
  if (array.isUndefined() || array.isNull() || !array["length"].isNumber())
    throw InputError(std::string("expected an array for '") + what + "'");
  return emscripten::convertJSArrayToNumberVector<T>(array);
}

// A vector as a typed array of the matching type owned by JS (a copy out of the wasm heap).
template <class T>
emscripten::val to_typed_array(const std::vector<T>& values) {
  return emscripten::val(emscripten::typed_memory_view(values.size(), values.data()))
      .call<emscripten::val>("slice");
}

// Any nlohmann JSON type (json, ordered_json); key order is kept.
template <class Json>
emscripten::val json_to_val(const Json& json) {
  return emscripten::val::global("JSON").call<emscripten::val>("parse", json.dump());
}

inline nlohmann::json val_to_json(const emscripten::val& value) {
  const std::string text = emscripten::val::global("JSON").call<std::string>("stringify", value);
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) throw InputError("a value passed to the core is not plain JSON data");
  return json;
}

// options[key] as a number, `fallback` when options or the key is undefined; InputError when the
// value is not a number.
inline double number_option(const emscripten::val& options, const char* key, double fallback) {
  if (options.isUndefined() || options.isNull()) return fallback;
  const emscripten::val value = options[key];
  if (value.isUndefined()) return fallback;
  if (!value.isNumber()) throw InputError(std::string("option '") + key + "' must be a number");
  return value.as<double>();
}

}  // namespace tessera::wasm
