#!/usr/bin/env bash
# End-to-end at 80x23, the pane tmux or screen leaves under its status line on an 80x24 window
# (issue 42): the session's prompts, its help, its graphics screen and apcs play run there, with
# the drawing area one row shorter and every text row shown (message, staff, key hint); each ends
# cleanly. Usage: tmux_80x23.sh APCS DATA_FOLDER
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder 80x23
cp "$data"/n-to-l/key1.dat "$data"/n-to-l/key2.dat "$data"/n-to-l/way1.dat "$work"/

start() { tmux -L "$socket" new-session -d -s "$1" -x 80 -y 23 -c "$work" "$2; echo EXITED=\$?; sleep 60"; }
fail() { fail_showing "$@"; }
# Line $2 (1-based) of session $1's screen.
line() { screen "$1" | sed -n "$2p"; }
# Fails unless line $2 of session $1 matches the extended regular expression $3.
expect_line() { line "$1" "$2" | grep -qE -- "$3" || fail "line $2 is not /$3/" "$1"; }
passed=0

# --- A text prompt and its help: the help's blank row under its title goes, its last row stays.
start prompt "LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --glyphs ascii"
wait_for prompt "Please keyin the KEY1 filename!"
[ "$(tmux -L "$socket" display -p -t prompt '#{pane_width}x#{pane_height}')" = 80x23 ] || fail "the pane is not 80x23"
screen prompt | grep -q "must be at least" && fail "80x23 was refused" prompt
keys_to prompt F1
wait_for prompt "APCS help - the keys of"
expect_line prompt 1 "^APCS help - the keys of"
expect_line prompt 2 "^  "
expect_line prompt 23 "^Any key closes this help\.$"
screen prompt | grep -qF "an empty line takes key1.dat" || fail "the help lost a line" prompt
keys_to prompt Space
wait_for prompt "Please keyin the KEY1 filename!"
keys_to prompt Escape
wait_for prompt "Quit APCS ? (Y/N)"
keys_to prompt y
wait_for prompt "EXITED=0"
passed=$((passed + 1))

# --- The graphics screen in each glyph set: the boundary in rows 1-17, the message in 18, the
# staff in 19-22, the key hint in 23; q and Y end the session with exit 0.
printf 'ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n' > "$work/graphics.keys"
for glyphs in ascii braille blocks; do
  start "$glyphs" "LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --glyphs $glyphs --keys graphics.keys"
  wait_for "$glyphs" "8 : Global Control"
  expect_line "$glyphs" 18 "^ 8 : Global Control    2 : Local Control"
  expect_line "$glyphs" 19 "^ TENSION .*\+0\.00"
  expect_line "$glyphs" 20 "^ CONTINUITY .*\+0\.00"
  expect_line "$glyphs" 21 "^ BIAS .*\+0\.00"
  expect_line "$glyphs" 22 "^ ACCELERATION .*\+0\.00"
  expect_line "$glyphs" 23 "^ W waypoints .*q quit"
  # The drawing area's boundary: its top row first, its bottom row (17) as wide as the screen, the
  # sides on every row between; the two control points at the path's ends are on it.
  [ "$(line "$glyphs" 17 | sed 's/ *$//' | wc -m)" -ge 81 ] || fail "no boundary in row 17 ($glyphs)" "$glyphs"
  for row in $(seq 2 16); do
    line "$glyphs" "$row" | grep -qE '^[^ ].{78}[^ ]$' || fail "row $row has no sides ($glyphs)" "$glyphs"
  done
  [ "$(screen "$glyphs" | head -17 | grep -o x | wc -l)" -ge 3 ] || fail "control points missing ($glyphs)" "$glyphs"
  keys_to "$glyphs" 2
  wait_for "$glyphs" "Local: 4/6 move the arrow, Enter picks the FIRST control point"
  expect_line "$glyphs" 18 "^ Local: 4/6 move the arrow"
  keys_to "$glyphs" q
  wait_for "$glyphs" "(Y/N)"
  keys_to "$glyphs" Y
  wait_for "$glyphs" "EXITED=0"
  passed=$((passed + 1))
done

# --- apcs play: frames with their number on the message row, the keys on the last; Esc, the
# overlay of all frames, and a key ends it with exit 0.
start play "LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' play '$data/car/car.scn' --glyphs braille --delay 60"
wait_for play "of 60: car.scn"
expect_line play 18 "^ Frame [0-9]+ of 60: car\.scn"
expect_line play 23 "^ Esc stop  Space pause"
keys_to play Escape
wait_for play "Press any key to see all frames"
keys_to play x
wait_for play "Press any key to end APCS"
line play 18 | grep -q "Press any key to end APCS" || line play 23 | grep -q "Press any key to end APCS" ||
  fail "the end's line is not on a text row" play
keys_to play x
wait_for play "EXITED=0"
passed=$((passed + 1))
echo "$passed passed, 0 failed"
