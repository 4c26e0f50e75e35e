#!/usr/bin/env bash
# Build and test from scratch on Debian 12: install the packages, configure and build the `ci`
# preset (warnings are errors), build the executable once more with CMake's default Makefile
# generator, run every test with ctest, then fuzz the AVUnit, WMG SDL, CH-Scenario and accident front
# ends for a minute each. This is what CI runs (.ci/run).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh

cmake --preset ci
cmake --build --preset ci -j2

# What most users type: CMake's default generator (Makefiles), unoptimised. The presets use Ninja,
# which hid a Makefile-only break once; building the executable this way keeps it from coming back.
cmake -S . -B build/make -G "Unix Makefiles" -DCMAKE_BUILD_TYPE= >/dev/null
cmake --build build/make -j2 --target scenfuzz

ctest_log=$(mktemp)
trap 'rm -f "$ctest_log"' EXIT
set +e
ctest --preset ci 2>&1 | tee "$ctest_log"
ctest_status=${PIPESTATUS[0]}
set -e

fuzz_status=0
if ((ctest_status == 0)); then
  bash scripts/fuzz.sh 60 || fuzz_status=$?
fi

# ctest's summary closes the output, after the fuzzer's report.
echo
echo "== summary"
((fuzz_status == 0)) || echo "fuzzing FAILED (scripts/fuzz.sh exit $fuzz_status)"
((ctest_status == 0)) || echo "ctest FAILED; fuzzing skipped"
grep -E '^(100% tests passed|[0-9]+% tests passed|The following tests|[[:space:]]+[0-9]+ - |Total Test time)' \
  "$ctest_log" || true
((ctest_status == 0 && fuzz_status == 0))
