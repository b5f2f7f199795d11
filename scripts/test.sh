#!/usr/bin/env bash
# Installs what is missing, builds with Clang, AddressSanitizer and UBSan (the clang-asan preset:
# -O1, -Werror, Ninja) and runs every test once with CTest: each test file's Catch2 cases in a
# random order in one process, each replay, fuzz corpus and end-to-end script on its own. A
# heap-use-after-free or undefined behaviour ends the test it is in. (CI, .ci/run, runs this and
# the Debian package's build with its tests: GCC's warnings and the optimised, hardened program.)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh clang
# A build folder made by an older APCS with Make cannot be reused by Ninja: start it afresh.
if grep -qs '^CMAKE_GENERATOR:INTERNAL=Unix Makefiles$' build/clang-asan/CMakeCache.txt; then
  rm -rf build/clang-asan
fi
cmake --preset clang-asan >/dev/null
cmake --build --preset clang-asan -j"$(nproc)"
# APCS_APPROVE would turn every golden comparison into an approval: the tests compare.
unset APCS_APPROVE
status=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT
ctest --preset clang-asan -j"$(nproc)" 2>&1 | tee "$log" || status=$?
# CI (APCS_REQUIRE_EVERY_TEST) has installed every tool the tests need: a skip there is a failure.
if [ -n "${APCS_REQUIRE_EVERY_TEST:-}" ] && grep -q "^The following tests did not run:" "$log"; then
  echo "FAILED: tests reported a skip (above), and APCS_REQUIRE_EVERY_TEST requires every test to run"
  status=1
fi
# No test may leave a program running (scripts/programs_left.sh says why).
bash scripts/programs_left.sh build/clang-asan || status=1
exit "$status"
