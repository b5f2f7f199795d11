#!/usr/bin/env bash
# --pixels against a terminal that answers device attributes with its reply and 137, 1,000 and
# 10,000 more bytes at once (pixel_flood.py): the session and `apcs play` still end on their
# quitting keys. 137 bytes overran curses' input queue and spun for good (issue 45, item 1).
# Usage: pixel_flood.sh APCS DATA_FOLDER
set -uo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
here=$(cd "$(dirname "$0")" && pwd)
command -v python3 > /dev/null || { echo "skipped: no python3"; exit 77; }
for mode in session play; do
  for extra in 137 1000 10000; do
    timeout 120 python3 "$here/pixel_flood.py" "$1" "$2" "$mode" "$extra" || exit 1
  done
done
