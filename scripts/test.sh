#!/usr/bin/env bash
# npm test: set up what is missing, build, then run every suite:
#   ctest (native C++), the same under ASan + UBSan, every fuzz target for 20 s
#   (TESSERA_FUZZ_SECONDS), node tests of the wasm module, Vitest unit tests, Playwright browser tests.
# Every suite runs even if an earlier one failed; the last line sums up; exit 1 on any failure.
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh || exit 1
bash scripts/build.sh all || { echo "tessera tests: build failed, 0 suites run"; exit 1; }

passed=()
failed=()
run_suite() {
  local name=$1
  shift
  echo "=== $name: $*"
  if "$@"; then passed+=("$name"); else failed+=("$name"); fi
}

jobs=$(nproc 2>/dev/null || echo 2)
run_suite ctest ctest --test-dir build/native --output-on-failure -j"$jobs"
run_suite sanitize bash -c "bash scripts/build.sh sanitize >build/sanitize-build.log 2>&1 ||
  { tail -n 40 build/sanitize-build.log; exit 1; }
  ctest --test-dir build/sanitize --output-on-failure -j$jobs"
run_suite fuzz bash scripts/fuzz.sh "${TESSERA_FUZZ_SECONDS:-20}"
run_suite wasm node --test tests/wasm/
run_suite vitest npm run --silent test:web
run_suite browser npm run --silent test:browser

echo
echo "tessera test suites: ${#passed[@]} passed, ${#failed[@]} failed${failed:+ (${failed[*]})}"
[ "${#failed[@]}" -eq 0 ]
