#!/usr/bin/env bash
# --pixels inside tmux (SPEC §7.2.1): tmux 3.3 passes neither sixel nor kitty pictures, so even an
# explicit --pixels sixel falls back to characters at once, asking the terminal nothing, with one
# line saying why; the session goes on in characters and ends as usual. auto and kitty too, and
# apcs play.
# Usage: tmux_pixels_fallback.sh APCS DATA_FOLDER
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder pixels
cp "$data"/key1.dat "$data"/key2.dat "$data"/way1.dat "$work"/
printf 'ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n8\n' > "$work/path.keys"
notice="pixels off: tmux passes no sixel or kitty pictures; run apcs outside it"

for choice in sixel auto kitty; do
  start_80x24 "$choice" "LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --glyphs ascii --pixels $choice --keys path.keys"
  # The line shows from the first screen on; the replay ends on the path screen's staff, in
  # characters (the drawing area in ASCII), the line still there.
  wait_for "$choice" "ACCELERATION"
  screen "$choice" | grep -qF "$notice" || fail_showing "--pixels $choice: no line saying why" "$choice"
  screen "$choice" | head -18 | grep -q "x" || fail_showing "--pixels $choice: no control point in characters" "$choice"
  # The line stays until a key is typed, then the key-hint row is the session's again.
  keys_to "$choice" 6
  sleep 0.3
  screen "$choice" | grep -qF "$notice" && fail_showing "--pixels $choice: the line outlived a key" "$choice"
  screen "$choice" | grep -q "+0.05" || fail_showing "--pixels $choice: the staff key did not act" "$choice"
  keys_to "$choice" q
  keys_to "$choice" Y
  wait_for "$choice" "EXITED=0"
done
# apcs play's animation too.
start_80x24 play "LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' play '$data/../robot/robot.scn' --glyphs ascii --pixels sixel"
wait_for play "$notice"
wait_for play "robot.scn"
keys_to play q
wait_for play "EXITED=0"
echo "passed: --pixels sixel, auto and kitty inside tmux (and apcs play's) fall back to characters with: $notice"
