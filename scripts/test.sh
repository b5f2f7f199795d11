#!/usr/bin/env bash
# Installs what is missing, builds the dev preset (GCC, Debug, -Werror, Ninja) and runs every test
# with CTest, the Catch2 cases each on its own and once more all together in a random order.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# A build folder made by an older APCS with Make cannot be reused by Ninja: start it afresh.
if grep -qs '^CMAKE_GENERATOR:INTERNAL=Unix Makefiles$' build/dev/CMakeCache.txt; then
  rm -rf build/dev
fi
cmake --preset dev >/dev/null
cmake --build --preset dev -j"$(nproc)"
ctest --preset dev -j"$(nproc)"
