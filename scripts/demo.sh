#!/usr/bin/env bash
# Build scenfuzz on a fresh Debian 12 machine and show what it does: search a logical scenario
# for failing concrete scenarios (the main job), check a scenario, print its parameter space, show
# a map, simulate one point, and judge a formula on a CSV log.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh
cmake --preset ci >/dev/null
cmake --build --preset ci -j2 --target scenfuzz

scenfuzz=build/ci/bin/scenfuzz
scenario=corpora/avunit/cut_in_multilane.avu

run() {
  echo
  echo "\$ scenfuzz $*"
  "$scenfuzz" "$@"
}

run --version

# The main job: 500 simulations of a cut-in (built-in map, so no shared data needed). Exit status
# 1 means findings, each written as a concrete scenario with its trace and picture.
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
status=0
run --budget 500 --seed 1 --out "$out/fuzz" corpora/avunit/cut_in_straight.avu || status=$?
echo "(exit status $status)"
ls "$out/fuzz" "$out/fuzz/findings" | head -12
echo
head -3 "$out/fuzz/findings/001-no_collision.avu"

run check "$scenario" && echo "(no output: no errors, no warnings)"
run space "$scenario"
run space --json "$scenario"

# The same file with a typo on its first range: check names the place and exits with 2.
broken=$(mktemp --suffix=.avu)
trap 'rm -f "$broken"; rm -rf "$out"' EXIT
sed '0,/range(/s//rnage(/' "$scenario" >"$broken"
status=0
run check "$broken" || status=$?
echo "(exit status $status)"

# A map, and a simulation of a logical scenario at the middle of its space (built-in map, so no
# shared data needed): what happened, and the trace and picture it wrote.
run map crossroads
status=0
run run corpora/avunit/red_light_runner_crossroads.avu --at mid --out "$out/run" || status=$?
echo "(exit status $status: 1 when a spec is violated)"
ls "$out/run"
