#!/usr/bin/env bash
# The test binary built by Clang with AddressSanitizer and UBSan (cmake --preset clang-asan), run
# on what GCC alone would let through: code whose result rests on the order in which a call's
# arguments are evaluated (GCC and Clang choose differently). The editors, the waypoint editor, the
# path document, the teaching keys (not their random streams: GCC's asan run has them), the replays
# and the session fuzz corpora run; a heap-use-after-free ends the run.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash scripts/install-deps.sh clang ninja-build
cmake --preset clang-asan >/dev/null
cmake --build --preset clang-asan --target apcs_tests
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Catch2 prints its own summary; the closing line counts for CI's reader.
build/clang-asan/tests/apcs_tests "[editor],[waypoints],[teaching]~[random],[document],[replay],[fuzz]"
