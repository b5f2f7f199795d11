#!/usr/bin/env bash
# Installs what is missing, builds the release preset and starts the interactive APCS session on
# the bundled example (data/n-to-l: the letter N becoming the letter L, thesis Ch. 5). The example
# is copied to build/session-n-to-l first, so that the session's files never touch data/.
# Extra arguments go to apcs (e.g. --glyphs ascii).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)" --target apcs
work=build/session-n-to-l
mkdir -p "$work"
cp data/n-to-l/*.dat "$work"/
echo "APCS works in $work. Press Enter at each prompt for the thesis' example answers;"
echo "answer way1.dat for the first path to see the staff bend it (README: your first session)."
exec build/release/apcs --workdir "$work" "$@"
