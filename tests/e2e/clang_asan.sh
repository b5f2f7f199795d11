#!/usr/bin/env bash
# Every test again with the program and the tests built by Clang with AddressSanitizer and UBSan
# (cmake --preset clang-asan): another compiler's warnings (-Werror) and order of evaluation of a
# call's arguments, and the sanitizers on every Catch2 case, replay, fuzz corpus and end-to-end
# script. The random-order run of all Catch2 cases is left to the GCC build (scripts/test.sh):
# once per build is enough. A heap-use-after-free or undefined behaviour ends the test it is in.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash scripts/install-deps.sh clang
if grep -qs '^CMAKE_GENERATOR:INTERNAL=Unix Makefiles$' build/clang-asan/CMakeCache.txt; then
  rm -rf build/clang-asan
fi
cmake --preset clang-asan >/dev/null
cmake --build --preset clang-asan -j"$(nproc)"
ctest --preset clang-asan -j"$(nproc)"
