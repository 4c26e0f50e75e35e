#!/usr/bin/env bash
# Fuzz the front ends with libFuzzer, each for SECONDS (default 60): build avunit_fuzzer (AVUnit,
# scenest), wmg_fuzzer (WMG SDL levels 1 and 2), chs_fuzzer (CH-Scenario) and acc_fuzzer (the
# CarSim accident formalism) with preset `fuzz`
# (clang, ASan + UBSan, in build/fuzz); for each, re-run every saved regression input, then fuzz from a fresh corpus
# seeded with the project's scenario files. Exits non-zero on any crash, leak, timeout,
# out-of-memory or printer round-trip mismatch.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$(pwd)

seconds=${1:-60}
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "usage: scripts/fuzz.sh [SECONDS]" >&2; exit 1; }

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j2

shared=${SCENFUZZ_SHARED_DIR:-$root/../shared}
corpora=()
trap 'rm -rf "${corpora[@]}"' EXIT

# fuzz_one NAME REGRESSIONS LOG ARTIFACTS SEED_FOLDER...: regressions, then fuzzing, for
# build/fuzz/bin/NAME with tests/fuzz/<dictionary>; REGRESSIONS is relative to the repository.
fuzz_one() {
  local name=$1 dict=$2 regressions=$3 log=$4 artifacts=$5
  shift 5
  local fuzzer=$root/build/fuzz/bin/$name
  mkdir -p "$artifacts"

  fail() {
    echo
    echo "fuzz: $name FAILED: $1"
    echo "fuzz: last lines of $log:"
    tail -n 40 "$log" | sed 's/^/  | /'
    local found
    found=$(find "$artifacts" -maxdepth 1 -type f -newer "$log.start" 2>/dev/null || true)
    if [[ -n "$found" ]]; then
      echo "fuzz: input(s) that triggered it:"
      echo "$found" | sed 's/^/  /'
      echo "fuzz: add the file to $regressions/ (see its README.md), fix the bug, and"
      echo "      reproduce with: $fuzzer <file>"
    fi
    exit 1
  }

  touch "$log.start"

  # 1. Regressions: every saved input must pass (each is run once, no fuzzing).
  local saved=()
  mapfile -t saved < <(find "$root/$regressions" -type f ! -name README.md ! -name '.*' | sort)
  if ((${#saved[@]} > 0)); then
    echo "fuzz: $name: re-running ${#saved[@]} regression input(s) from $regressions/"
    "$fuzzer" -timeout=10 -rss_limit_mb=4096 "${saved[@]}" >"$log" 2>&1 ||
      fail "a regression input fails again"
  else
    echo "fuzz: $name: no regression inputs yet"
    : >"$log"
  fi

  # 2. Fuzzing, from a fresh corpus of every scenario file we have for this front end.
  local corpus n=0 source file
  corpus=$(mktemp -d "${TMPDIR:-/tmp}/scenfuzz-corpus.XXXXXX")
  corpora+=("$corpus")
  for source in "$@" "$root/$regressions"; do
    [[ -d "$source" ]] || continue
    while IFS= read -r -d '' file; do
      [[ "$(basename "$file")" == README.md ]] && continue
      n=$((n + 1))
      cp "$file" "$corpus/seed$n-$(basename "$file")"
    done < <(find "$source" -type f -print0)
  done
  echo "fuzz: $name: fuzzing for ${seconds}s from $n seed file(s); log in ${log#"$root"/}"

  "$fuzzer" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -dict="$root/tests/fuzz/$dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
    >>"$log" 2>&1 || fail "libFuzzer found a crash, leak, timeout or round-trip mismatch"

  local runs
  runs=$(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -Eo '[0-9]+$' ||
    echo "?")
  echo "fuzz: $name: OK: $runs inputs in ${seconds}s, no crash, leak or timeout"
}

fuzz_one avunit_fuzzer avunit.dict tests/fuzz/regressions "$root/build/fuzz/fuzz.log" \
  "$root/build/fuzz/artifacts" corpora/avunit tests/lang/data "$shared/examples/avunit" \
  "$shared/examples/scenest"

fuzz_one wmg_fuzzer wmg.dict tests/fuzz/regressions-wmg "$root/build/fuzz/wmg-fuzz.log" \
  "$root/build/fuzz/artifacts/wmg" corpora/wmg tests/lang/data/wmg

fuzz_one chs_fuzzer chs.dict tests/fuzz/regressions-chs "$root/build/fuzz/chs-fuzz.log" \
  "$root/build/fuzz/artifacts/chs" tests/lang/data/chs

fuzz_one acc_fuzzer acc.dict tests/fuzz/regressions-acc "$root/build/fuzz/acc-fuzz.log" \
  "$root/build/fuzz/artifacts/acc" corpora/accident tests/lang/data/accident
