#!/usr/bin/env bash
# Installs what building and running need (not the tests' tools), builds the release preset's apcs
# without the tests and starts the interactive APCS session on the bundled example (data/n-to-l:
# the letter N becoming the letter L, thesis Ch. 5). The example is copied to build/session-n-to-l
# first, so that the session's files never touch data/. Extra arguments go to apcs (e.g. --glyphs ascii).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --run
# Catch2 may be missing (install-deps.sh --run leaves it out): the tests are not configured here.
cmake --preset release -DAPCS_BUILD_TESTS=OFF >/dev/null
cmake --build --preset release -j"$(nproc)" --target apcs
work=build/session-n-to-l
mkdir -p "$work"
cp data/n-to-l/*.dat "$work"/
# Lines of at most 79 columns: an 80-column terminal wraps nothing mid-word.
hint="Press Enter at each prompt for the thesis' example answers; answer way1.dat
for the first path to see the staff bend it (README: your first session).
? shows the keys; Ctrl-C ends APCS at any step, q on a graphics screen
(at a text prompt q is typed)."
# The session's full screen covers whatever was printed before it: on a terminal the hint waits
# for Enter, and it is printed again after the session.
printf 'APCS works in %s.\n%s\n' "$work" "$hint"
[ -t 0 ] && read -r -p "Press Enter to start APCS. " _
status=0
build/release/apcs --workdir "$work" "$@" || status=$?
printf 'APCS worked in %s:\nits key frames, paths and in-between files are there.\n%s\n' "$work" "$hint"
exit "$status"
