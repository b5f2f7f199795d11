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
status=0
ctest --preset clang-asan -j"$(nproc)" || status=$?
# No test may leave a program running (scripts/programs_left.sh says why).
bash scripts/programs_left.sh build/clang-asan || status=1
exit "$status"
