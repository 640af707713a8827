// The one progress/cancel mechanism: long stages take a Progress and call step() now and then.
// step() reports (stage, fraction in [0,1]) to whoever listens (CLI stderr, the wasm worker) and
// throws CancelledError when the cancel flag is set.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "base/error.h"

namespace tessera {

class Progress {
 public:
  using Listener = std::function<void(const std::string& stage, double fraction)>;

  Progress() = default;
  explicit Progress(Listener listener, const std::atomic<bool>* cancel = nullptr)
      : listener_(std::move(listener)), cancel_(cancel) {}

  void step(const std::string& stage, double fraction) const {
    if (cancel_ && cancel_->load(std::memory_order_relaxed)) throw CancelledError();
    if (listener_) listener_(stage, fraction);
  }

 private:
  Listener listener_;
  const std::atomic<bool>* cancel_ = nullptr;
};

}  // namespace tessera
