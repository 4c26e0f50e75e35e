#!/usr/bin/env bash
# Build scenfuzz on a fresh Debian 12 machine and show what it does today: check a logical
# scenario, print its parameter space, show a map, and simulate a scenario.
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
run check "$scenario" && echo "(no output: no errors, no warnings)"
run space "$scenario"
run space --json "$scenario"

# The same file with a typo on its first range: check names the place and exits with 2.
broken=$(mktemp --suffix=.avu)
trap 'rm -f "$broken"' EXIT
sed '0,/range(/s//rnage(/' "$scenario" >"$broken"
status=0
run check "$broken" || status=$?
echo "(exit status $status)"

# A map, and a simulation of a logical scenario at the middle of its space (built-in map, so no
# shared data needed): what happened, and the trace and picture it wrote.
run map crossroads
out=$(mktemp -d)
trap 'rm -f "$broken"; rm -rf "$out"' EXIT
run run corpora/avunit/red_light_runner_crossroads.avu --at mid --out "$out"
ls "$out"
