#!/usr/bin/env bash
# Fuzz the AVUnit front end with libFuzzer for SECONDS (default 60): build avunit_fuzzer (preset
# `fuzz`: clang, ASan + UBSan, in build/fuzz), re-run every saved regression input, then fuzz from
# a fresh corpus seeded with the project's scenario files. Exits non-zero on any crash, leak,
# timeout, out-of-memory or printer round-trip mismatch.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$(pwd)

seconds=${1:-60}
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "usage: scripts/fuzz.sh [SECONDS]" >&2; exit 1; }

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j2

fuzzer=$root/build/fuzz/bin/avunit_fuzzer
dict=$root/tests/fuzz/avunit.dict
regressions=$root/tests/fuzz/regressions
artifacts=$root/build/fuzz/artifacts/
mkdir -p "$artifacts"
log=$root/build/fuzz/fuzz.log

fail() {
  echo
  echo "fuzz: FAILED: $1"
  echo "fuzz: last lines of $log:"
  tail -n 40 "$log" | sed 's/^/  | /'
  local found
  found=$(find "$artifacts" -type f -newer "$log.start" 2>/dev/null || true)
  if [[ -n "$found" ]]; then
    echo "fuzz: input(s) that triggered it:"
    echo "$found" | sed 's/^/  /'
    echo "fuzz: add the file to tests/fuzz/regressions/ (see its README.md), fix the bug, and"
    echo "      reproduce with: $fuzzer <file>"
  fi
  exit 1
}

touch "$log.start"

# 1. Regressions: every saved input must pass (each is run once, no fuzzing).
mapfile -t saved < <(find "$regressions" -type f ! -name README.md ! -name '.*' | sort)
if ((${#saved[@]} > 0)); then
  echo "fuzz: re-running ${#saved[@]} regression input(s) from tests/fuzz/regressions/"
  "$fuzzer" -timeout=10 -rss_limit_mb=4096 "${saved[@]}" >"$log" 2>&1 ||
    fail "a regression input fails again"
else
  echo "fuzz: no regression inputs yet"
fi

# 2. Fuzzing, from a fresh corpus of every scenario file we have.
corpus=$(mktemp -d "${TMPDIR:-/tmp}/scenfuzz-corpus.XXXXXX")
trap 'rm -rf "$corpus"' EXIT
shared=${SCENFUZZ_SHARED_DIR:-$root/../shared}
n=0
for source in corpora/avunit tests/lang/data "$regressions" "$shared/examples/avunit" \
  "$shared/examples/scenest"; do
  [[ -d "$source" ]] || continue
  while IFS= read -r -d '' file; do
    [[ "$(basename "$file")" == README.md ]] && continue
    n=$((n + 1))
    cp "$file" "$corpus/seed$n-$(basename "$file")"
  done < <(find "$source" -type f -print0)
done
echo "fuzz: fuzzing for ${seconds}s from $n seed file(s); log in build/fuzz/fuzz.log"

"$fuzzer" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -dict="$dict" \
  -artifact_prefix="$artifacts" -print_final_stats=1 >>"$log" 2>&1 ||
  fail "libFuzzer found a crash, leak, timeout or round-trip mismatch"

runs=$(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -Eo '[0-9]+$' || echo "?")
echo "fuzz: OK: $runs inputs in ${seconds}s, no crash, leak or timeout"
