#!/bin/bash
# Whether two scenfuzz binaries simulate the corpus alike: `scenfuzz run --at random` on every
# scenario in corpora/ at seeds 1 and 2 with each, and their trace.csv compared byte for byte.
# For changes meant to keep every trace (performance work): prints each scenario whose trace
# differs and "runs N differ M"; exits 1 when any differs.
#   scripts/compare-traces.sh OLD_SCENFUZZ NEW_SCENFUZZ [MAP_PATH]
set -u
if [ $# -lt 2 ]; then
  echo "usage: $0 OLD_SCENFUZZ NEW_SCENFUZZ [MAP_PATH]" >&2
  exit 2
fi
old=$1 new=$2
export SCENFUZZ_MAP_PATH=${3:-${SCENFUZZ_MAP_PATH:-../shared/maps/apollo}}
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
runs=0 differ=0
for file in "$root"/corpora/avunit/*.avu "$root"/corpora/law/*.scenest "$root"/corpora/wmg/*.sdl \
  "$root"/corpora/benchmarks/*.avu; do
  for seed in 1 2; do
    name=$(basename "$file").$seed
    "$old" run "$file" --at random --seed "$seed" --out "$out/old.$name" > "$out/old.$name.txt" 2>&1
    "$new" run "$file" --at random --seed "$seed" --out "$out/new.$name" > "$out/new.$name.txt" 2>&1
    runs=$((runs + 1))
    if ! cmp -s "$out/old.$name/trace.csv" "$out/new.$name/trace.csv"; then
      differ=$((differ + 1))
      echo "differs: $name"
    fi
  done
done
echo "runs $runs differ $differ"
[ "$differ" -eq 0 ]
