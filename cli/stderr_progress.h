// The one progress printer of the CLI: "tessera: <stage> <percent>%" on stderr, each stage at
// every quarter, so that long runs show they are alive without flooding the terminal.
#pragma once

#include "base/progress.h"

namespace tessera::cli {

Progress stderr_progress();

}  // namespace tessera::cli
