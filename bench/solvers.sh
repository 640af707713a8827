#!/usr/bin/env bash
# P1 solvers side by side (issue 5): Tessera's exact solver, GLPK plain and tuned (tessera solve),
# glpsol --lp and cbc on the very same instances, one after the other on this machine. Checks
# that every optimal objective agrees and prints a table with the speed-up of the exact solver
# and the median ratios (bench/solvers_table.mjs).
#
#   bench/solvers.sh [instance-dir] [--time-limit S]
#
# An instance is a pair <name>.json / <name>.lp (tessera solve reads the JSON, glpsol and cbc the
# LP form of the same program). Without a directory, synthetic instances are generated first into
# build/bench-p1 by tessera_p1_instances (bench/p1_instances.cpp) and the table says so.
# Times are CPU seconds (user + system) of each process, file reading included; wall seconds are
# kept in the TSV written next to the instances (solvers.tsv).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tessera=${TESSERA:-$root/build/native/cli/tessera}
generator=$root/build/native/bench/tessera_p1_instances
limit=60
dir=""
while [ $# -gt 0 ]; do
  case $1 in
    --time-limit) limit=$2; shift 2 ;;
    --help|-h) sed -n 2,14p "$0"; exit 0 ;;
    *) dir=$1; shift ;;
  esac
done
for tool in "$tessera" glpsol cbc node /usr/bin/time; do
  command -v "$tool" >/dev/null || { echo "solvers.sh: $tool is missing (build, or install glpk-utils, coinor-cbc)"; exit 2; }
done
synthetic=0
if [ -z "$dir" ]; then
  dir=$root/build/bench-p1
  synthetic=1
  [ -x "$generator" ] || { echo "solvers.sh: build tessera_p1_instances first"; exit 2; }
  "$generator" "$dir" >/dev/null || exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
tsv=$dir/solvers.tsv
printf 'instance\tedges\tconflicts\tsolver\tstatus\tobjective\tcpu\twall\n' > "$tsv"

# Runs a command under /usr/bin/time; sets cpu and wall.
timed() {
  /usr/bin/time -f "%e %U %S" -o "$tmp/time" "$@" > "$tmp/out" 2> "$tmp/err"
  read -r wall user system < <(tail -n 1 "$tmp/time")
  cpu=$(echo "$user + $system" | bc -l)
}

json_field() { sed -n "s/^  \"$1\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" "$tmp/out" | head -n 1; }

for lp in "$dir"/*.lp; do
  name=$(basename "${lp%.lp}")
  json=${lp%.lp}.json
  [ -f "$json" ] || json=$lp
  edges=""; conflicts=""
  for solver in exact glpk glpk-tuned; do
    timed "$tessera" solve "$json" --solver "$solver" --time-limit "$limit" --json
    status=$(json_field status); objective=$(json_field objective)
    edges=$(sed -n 's/^    "edges": \([0-9]*\),\{0,1\}$/\1/p' "$tmp/out")
    conflicts=$(sed -n 's/^    "conflicts": \([0-9]*\)$/\1/p' "$tmp/out")
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$edges" "$conflicts" "$solver" \
      "${status:-error}" "$objective" "$cpu" "$wall" >> "$tsv"
  done
  timed glpsol --lp "$lp" --tmlim "$limit" -o "$tmp/glpsol.txt"
  case $(sed -n 's/^Status: *//p' "$tmp/glpsol.txt" 2>/dev/null) in
    "INTEGER OPTIMAL") status=optimal ;;
    "INTEGER EMPTY") status=infeasible ;;
    "INTEGER NON-OPTIMAL") status=feasible ;;
    *) status=time_limit ;;
  esac
  objective=$(sed -n 's/^Objective: *[^=]*= *\([-0-9.e+]*\).*/\1/p' "$tmp/glpsol.txt" 2>/dev/null)
  printf '%s\t%s\t%s\tglpsol\t%s\t%s\t%s\t%s\n' "$name" "$edges" "$conflicts" "$status" \
    "$objective" "$cpu" "$wall" >> "$tsv"
  timed cbc "$lp" sec "$limit" solve
  case $(grep -m1 '^Result - ' "$tmp/out") in
    *"Optimal solution found"*) status=optimal ;;
    *"infeasible"*) status=infeasible ;;
    *) status=$(grep -q '^Objective value' "$tmp/out" && echo feasible || echo time_limit) ;;
  esac
  objective=$(sed -n 's/^Objective value: *//p' "$tmp/out" | head -n 1)
  printf '%s\t%s\t%s\tcbc\t%s\t%s\t%s\t%s\n' "$name" "$edges" "$conflicts" "$status" \
    "$objective" "$cpu" "$wall" >> "$tsv"
  echo "solvers.sh: $name done" >&2
done
node "$root/bench/solvers_table.mjs" "$tsv" "$limit" "$synthetic"
