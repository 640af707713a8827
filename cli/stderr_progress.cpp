#include "stderr_progress.h"

#include <cstdio>
#include <string>

namespace tessera::cli {

Progress stderr_progress() {
  return Progress(
      [last = std::string(), quarter = -1](const std::string& stage, double fraction) mutable {
        const int now = static_cast<int>(fraction * 4);
        if (stage == last && now == quarter) return;
        last = stage;
        quarter = now;
        std::fprintf(stderr, "tessera: %s %d%%\n", stage.c_str(), now * 25);
      });
}

}  // namespace tessera::cli
