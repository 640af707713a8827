// The boundary between C++ and JS: every bound function runs inside guard(), which turns a
// tessera::Error into a JS Error carrying the C++ message and the error's kind, and std::bad_alloc
// into a 'limit' error, so nothing aborts the module.
#pragma once

#include <emscripten/val.h>

#include <new>
#include <string>

#include "base/error.h"

namespace tessera::wasm {

[[noreturn]] inline void throw_js_error(const std::string& message, const std::string& kind) {
  emscripten::val error = emscripten::val::global("Error").new_(message);
  error.set("kind", kind);
  error.throw_();
}

// The core names the command-line option that raises a limit; the page cannot take options.
inline constexpr const char* kPageLimitNote =
    ". In the browser the limits are fixed so that the tab stays alive; the tessera command line "
    "takes the option to raise them.";

template <class F>
emscripten::val guard(F&& body) {
  try {
    return body();
  } catch (const LimitError& e) {
    throw_js_error(std::string(e.what()) + kPageLimitNote, e.kind());
  } catch (const Error& e) {
    throw_js_error(e.what(), e.kind());
  } catch (const std::bad_alloc&) {
    throw_js_error("out of memory: the input needs more than the page's memory cap", "limit");
  } catch (const std::exception& e) {
    throw_js_error(std::string("internal error: ") + e.what(), "internal");
  }
}

}  // namespace tessera::wasm
