#!/usr/bin/env bash
# Installs what is missing, builds the release preset and starts APCS on the bundled example data.
# Extra arguments go to apcs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target apcs
example=data/n-to-l
exec build/release/apcs path "$example/way1.dat" --print "$@"
