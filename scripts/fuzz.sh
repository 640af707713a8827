#!/usr/bin/env bash
# npm run fuzz -- [seconds]: builds the libFuzzer targets (the sanitizer build, clang-14 with ASan
# + UBSan, in build/sanitize), writes their seed corpora, and runs every target for the given
# seconds (default 60), as many at a time as there are cores. An input slower than 2 s, a crash, a
# leak or a sanitizer report fails the run; the input is kept in build/fuzz/findings/ to become a
# regression test.
set -uo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
jobs=$(nproc 2>/dev/null || echo 2)

mkdir -p build
bash scripts/build.sh sanitize >build/sanitize-build.log 2>&1 ||
  { tail -n 40 build/sanitize-build.log; exit 1; }
bin=build/sanitize/tests/fuzz

corpus=build/fuzz/corpus
findings=build/fuzz/findings
mkdir -p build "$corpus" "$findings"
"$bin"/make_seeds "$corpus" data/regmaps/catalog_g2-101.tsv || exit 1

run_target() {
  local target=$1
  mkdir -p "$corpus/$target" "$findings/$target"
  if "$bin/$target" "$corpus/$target" -max_total_time="$seconds" -timeout=2 \
    -rss_limit_mb=2048 -max_len=65536 -artifact_prefix="$findings/$target/" -print_final_stats=1 \
    >"build/fuzz/$target.log" 2>&1; then
    echo "fuzz $target: ok, $(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' \
      "build/fuzz/$target.log" | grep -o '[0-9]*$') executions in ${seconds}s"
  else
    echo "fuzz $target: FAILED (log: build/fuzz/$target.log, input in $findings/$target/)"
    tail -n 30 "build/fuzz/$target.log"
    return 1
  fi
}

export -f run_target
export bin corpus findings seconds
targets=$(cd "$bin" && ls fuzz_* | grep -v '\.')
printf '%s\n' $targets | xargs -P "$jobs" -I{} bash -c 'run_target {}'
