#!/usr/bin/env bash
# P1 solvers side by side (issue 5): Tessera's exact solver, GLPK plain and tuned (tessera solve),
# glpsol --lp and cbc on the very same instances, one after the other on this machine. Checks
# that every optimal objective agrees and prints a table with the speed-up of the exact solver
# and the median ratios (bench/solvers_table.mjs).
#
#   bench/solvers.sh [--time-limit S] [--confirm S] [--meshes DIR] [instance-dir]
#
# Without an instance directory, the instances are made first, into build/bench-p1:
#   meshes/     program P1 of `tessera layout <mesh> --alpha A --export-p1` for every mesh of
#               ../shared/meshes (or --meshes DIR) and A in 0, 1, 5, 20; a mesh whose layout
#               stops before P1 (a limit, an error) is reported and has no instance;
#   loop-rounds/ the programs of the layout's loop rounds at those alphas (<mesh>_a<A>_r<k>: P1
#               with the loop conflicts of the rounds before, Ch. 5), where the slider's cold
#               re-solves spend most of their P1 time;
#   synthetic/  tessera_p1_instances (bench/p1_instances.cpp), shaped like thesis Appendix B.
# An instance is a pair <name>.json / <name>.lp (tessera solve reads the JSON, glpsol and cbc the
# LP form of the same program). Times are CPU seconds (user + system, 1 ms resolution) of each
# process, start-up and file reading included; wall seconds are kept in the TSV (solvers.tsv), and
# for exact, glpk and glpk-tuned the seconds of the solve alone ("seconds" of tessera solve --json:
# the model built and solved in one process, start-up and reading left out), which compare the
# solvers on small instances where start-up is most of a process's time.
# Where the exact solver proved an optimum and CBC did not finish, CBC runs again for up to
# --confirm seconds (default 600; 0: not at all) on the instance that `tessera reduce` leaves below
# that optimum plus 1e-7 relative (column "cbc reduced"): the edges that no matching so cheap can
# use are gone, by the LP dual checked against the instance (core/matching/dual_bound.h), so the
# optimum is the same unless a cheaper matching exists, which CBC would find. Unfinished, CBC runs
# once more on the whole instance with that cost as its cutoff (column "cbc cutoff"). Likewise
# where the exact solver proved an optimum and none of GLPK's runs (glpk, glpk-tuned, glpsol)
# finished: glpk-tuned on the reduced instance ("glpk reduced"), then on the whole one for up to
# --confirm seconds ("glpk long"). These answers count in the agreement, not in the speed-ups: the
# cost is a hint that the other solvers do not get.
# glpsol or cbc missing: that column is skipped with a message (scripts/setup.sh installs both).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tessera=${TESSERA:-$root/build/native/cli/tessera}
generator=$root/build/native/bench/tessera_p1_instances
meshes=$root/../shared/meshes
alphas=(0 1 5 20)
limit=60
confirm=600
dir=""
while [ $# -gt 0 ]; do
  case $1 in
    --time-limit) limit=$2; shift 2 ;;
    --confirm) confirm=$2; shift 2 ;;
    --meshes) meshes=$2; shift 2 ;;
    --help|-h) sed -n 2,31p "$0"; exit 0 ;;
    *) dir=$1; shift ;;
  esac
done
for tool in "$tessera" node; do
  command -v "$tool" >/dev/null || { echo "solvers.sh: $tool is missing (build first)"; exit 2; }
done
tools=()
for tool in glpsol cbc; do
  if command -v "$tool" >/dev/null; then tools+=("$tool"); else
    echo "solvers.sh: $tool is not installed, its column is skipped (scripts/setup.sh)" >&2
  fi
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The P1 instances of every shared mesh's layout at each alpha; one line per mesh on stderr. The
# separatrices may grow for 300 s (the CLI's default stops at 60 s, which dragon's graph nears on a
# busy machine): the instances are the same whatever the load.
make_mesh_instances() {
  local out=$1 rounds=$2 mesh name alpha made
  mkdir -p "$out" "$rounds"
  for mesh in "$meshes"/*.obj "$meshes"/*.off; do
    [ -f "$mesh" ] || continue
    name=$(basename "${mesh%.*}")
    made=()
    for alpha in "${alphas[@]}"; do
      if ! "$tessera" layout "$mesh" --alpha "$alpha" --export-p1 "$out" --max-solve-seconds 5 \
        --max-trace-seconds 300 > /dev/null 2> "$tmp/layout.err"; then
        echo "solvers.sh: $name: no P1 instance at alpha $alpha, the layout stopped: $(grep -m1 'error' "$tmp/layout.err")" >&2
        break
      fi
      mv "$out/${name}_a${alpha}"_r* "$rounds" 2> /dev/null
      made+=("$alpha")
    done
    [ ${#made[@]} -gt 0 ] && echo "solvers.sh: $name: instances at alpha ${made[*]}" >&2
  done
}

# Runs a command; sets cpu (user + system seconds of the command, from the shell's children times
# taken right before and after it, so that the parsing here is not counted) and wall.
children_seconds() {
  tail -n 1 "$1" | sed 's/m/ /g; s/s//g' | awk '{ printf "%.3f", 60 * $1 + $2 + 60 * $3 + $4 }'
}
timed() {
  times > "$tmp/before"
  local start=$EPOCHREALTIME
  "$@" > "$tmp/out" 2> "$tmp/err"
  local end=$EPOCHREALTIME
  times > "$tmp/after"
  cpu=$(echo "$(children_seconds "$tmp/after") - $(children_seconds "$tmp/before")" | bc -l)
  wall=$(echo "$end - $start" | bc -l)
}

json_field() { sed -n "s/^  \"$1\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" "$tmp/out" | head -n 1; }

# row solver status objective [solve-seconds]
row() { printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$group" "$name" "$edges" "$conflicts" "$1" "$2" "$3" "$cpu" "$wall" "${4:-}" >> "$tsv"; }

# Sets glpk_finished when a run of GLPK (its status $1) proved an optimum or infeasibility.
note_glpk() { [ "$1" = optimal ] || [ "$1" = infeasible ] && glpk_finished=yes; }

# solve_with_tessera solver [row time-limit]: the row of `tessera solve --solver solver`, named
# after the solver and with --time-limit unless given.
solve_with_tessera() {
  timed "$tessera" solve "$json" --solver "$1" --time-limit "${3:-$limit}" --json
  if [ -z "$edges" ]; then  # the instance's size, from its first run
    edges=$(sed -n 's/^    "edges": \([0-9]*\),\{0,1\}$/\1/p' "$tmp/out")
    conflicts=$(sed -n 's/^    "conflicts": \([0-9]*\)$/\1/p' "$tmp/out")
  fi
  local status; status=$(json_field status)
  row "${2:-$1}" "${status:-error}" "$(json_field objective)" "$(json_field seconds)"
  case $1 in
    exact) exact_status=$status && exact_objective=$(json_field objective) ;;
    glpk*) note_glpk "$status" ;;
  esac
}

solve_with_glpsol() {
  timed glpsol --lp "$lp" --tmlim "$limit" -o "$tmp/glpsol.txt"
  local status
  case $(sed -n 's/^Status: *//p' "$tmp/glpsol.txt" 2>/dev/null) in
    "INTEGER OPTIMAL") status=optimal ;;
    "INTEGER EMPTY") status=infeasible ;;
    "INTEGER NON-OPTIMAL") status=feasible ;;
    *) status=time_limit ;;
  esac
  row glpsol "$status" "$(sed -n 's/^Objective: *[^=]*= *\([-0-9.e+]*\).*/\1/p' "$tmp/glpsol.txt" 2>/dev/null)"
  note_glpk "$status"
}

# solve_with_cbc [cutoff]: the row "cbc", or with a cutoff (and the --confirm time) "cbc-cutoff".
solve_with_cbc() {
  if [ $# -eq 0 ]; then timed cbc "$lp" sec "$limit" solve; else
    timed cbc "$lp" cutoff "$1" sec "$confirm" solve
  fi
  row "cbc${1:+-cutoff}" "$(cbc_status)" "$(cbc_objective)"
  if [ $# -eq 0 ]; then cbc_status=$(cbc_status); fi
}

# The status and objective of the last cbc run.
cbc_status() {
  case $(grep -m1 -E '^Result - |^Problem is infeasible' "$tmp/out") in
    *"Optimal solution found"*) echo optimal ;;
    *"nfeasible"*) echo infeasible ;;
    *) grep -q '^Objective value' "$tmp/out" && echo feasible || echo time_limit ;;
  esac
}
cbc_objective() { sed -n 's/^Objective value: *//p' "$tmp/out" | head -n 1; }

# The exact solver's optimum plus 1e-7 relative: the cost of the confirmations.
confirm_cost() {
  awk -v x="$exact_objective" 'BEGIN { printf "%.12g", x + 1e-7 * (1 + (x < 0 ? -x : x)) }'
}

# The instance below confirm_cost(), once per instance, as $tmp/reduced.{lp,json}; false if
# `tessera reduce` failed.
reduce_instance() {
  [ -n "$reduced" ] && return "$reduced"
  reduced=1
  for form in lp json; do
    "$tessera" reduce "$json" --below "$(confirm_cost)" --output "$tmp/reduced.$form" \
      --time-limit "$confirm" > "$tmp/reduce.out" 2>&1 || return 1
  done
  echo "solvers.sh: $name reduced: $(sed 's/.*: below/below/; s/, in [^;]*;/;/' "$tmp/reduce.out")" >&2
  reduced=0
}

# CBC on the reduced instance, then with the cutoff, where the exact solver proved an optimum and
# CBC did not finish.
confirm_with_cbc() {
  [ "$confirm" != 0 ] && [ "$exact_status" = optimal ] && [ "$cbc_status" != optimal ] || return 0
  if reduce_instance; then
    timed cbc "$tmp/reduced.lp" sec "$confirm" solve
    row cbc-reduced "$(cbc_status)" "$(cbc_objective)"
    [ "$(cbc_status)" = optimal ] && return 0
  fi
  solve_with_cbc "$(confirm_cost)"
}

# glpk-tuned on the reduced instance, then on the whole one, for up to --confirm seconds each,
# where the exact solver proved an optimum and no run of GLPK finished.
confirm_with_glpk() {
  [ "$confirm" != 0 ] && [ "$exact_status" = optimal ] && [ -z "$glpk_finished" ] || return 0
  if reduce_instance; then
    local whole=$json
    json=$tmp/reduced.json
    solve_with_tessera glpk-tuned glpk-reduced "$confirm"
    json=$whole
    [ -n "$glpk_finished" ] && return 0
  fi
  solve_with_tessera glpk-tuned glpk-long "$confirm"
}

if [ -z "$dir" ]; then
  dir=$root/build/bench-p1
  rm -rf "$dir"
  make_mesh_instances "$dir/meshes" "$dir/loop-rounds"
  [ -x "$generator" ] || { echo "solvers.sh: build tessera_p1_instances first"; exit 2; }
  "$generator" "$dir/synthetic" > /dev/null || exit 1
fi
tsv=$dir/solvers.tsv
printf 'set\tinstance\tedges\tconflicts\tsolver\tstatus\tobjective\tcpu\twall\tsolve\n' > "$tsv"
for lp in "$dir"/*.lp "$dir"/*/*.lp; do
  [ -f "$lp" ] || continue
  name=$(basename "${lp%.lp}")
  group=$(basename "$(dirname "$lp")")
  json=${lp%.lp}.json
  [ -f "$json" ] || json=$lp
  edges=""; conflicts=""; exact_status=""; cbc_status=""; glpk_finished=""; reduced=""
  for solver in exact glpk glpk-tuned; do solve_with_tessera "$solver"; done
  for tool in "${tools[@]}"; do "solve_with_$tool"; done
  [[ " ${tools[*]} " == *" cbc "* ]] && confirm_with_cbc
  confirm_with_glpk
  echo "solvers.sh: $name done" >&2
done
node "$root/bench/solvers_table.mjs" "$tsv" "$limit"
