// A core Progress that calls a JS function onProgress(stage, fraction); undefined or null: silent.
#pragma once

#include <emscripten/val.h>

#include <string>

#include "base/progress.h"

namespace tessera::wasm {

inline Progress js_progress(const emscripten::val& on_progress) {
  if (on_progress.isUndefined() || on_progress.isNull()) return Progress();
  return Progress(
      [on_progress](const std::string& stage, double fraction) { on_progress(stage, fraction); });
}

}  // namespace tessera::wasm
