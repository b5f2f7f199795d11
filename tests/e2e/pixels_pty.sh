#!/usr/bin/env bash
# --pixels against terminals played by pixel_pty.py on a pseudo-terminal (no X needed):
#   silent:  a terminal that answers nothing: characters within the 100 ms limit, never a hang,
#            "no answer to device attributes" on the screen, and the keys still act;
#   late:    device attributes 0.3 s late: characters, and the late answer is not typed as keys;
#   csi16:   sixel, no pixels in TIOCGWINSZ: the cell size from CSI 16 t; unanswered: characters;
#   nopixel: device attributes without 4 and no kitty reply: characters, with why;
#   sixel:   attributes with 4 and the cell size in TIOCGWINSZ: the first path screen carries the
#            whole picture as sixel, each staff key only a band of it, smaller than the whole;
#            Ctrl-L sends the whole picture again, and so does a resize, at the new size.
# Usage: pixels_pty.sh APCS DATA_FOLDER
set -uo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
here=$(cd "$(dirname "$0")" && pwd)
command -v python3 > /dev/null || { echo "skipped: no python3"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

run() {
  rm -rf "$work/session" && mkdir "$work/session"
  cp "$data/key1.dat" "$data/key2.dat" "$data/way1.dat" "$work/session/"
  printf 'ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n8\n' > "$work/session/path.keys"
  timeout 60 python3 "$here/pixel_pty.py" "$apcs" "$work/session" "$@" > "$work/$1.out" ||
    fail "$1: $(cat "$work/$1.out")"
}

run silent 2
grep -qF "notice pixels off: no answer to device attributes within 100 ms" "$work/silent.out" ||
  fail "silent: no fallback line: $(cat "$work/silent.out")"
# The path screen is there once the replay is through and the output has been quiet 0.4 s. A
# session that waited on the silent terminal for each question (a hang, not the 100 ms limit)
# would take the 20 s the script allows; 5 s leaves a CI machine building beside the tests room.
read -r _ _ picture ms < <(grep '^first-screen' "$work/silent.out")
[ "$picture" -eq 0 ] || fail "silent: a picture was sent"
[ "$ms" -lt 5000 ] || fail "silent: the first screen took $ms ms"

# An answer that comes after the limit reaches the session as input: dropped whole, never typed
# (its Esc would leave TENSION, its digits move a staff line): one 6 sets TENSION alone.
run late 1
grep -qF "notice pixels off: no answer to device attributes within 100 ms" "$work/late.out" ||
  fail "late: no fallback line: $(cat "$work/late.out")"
grep -qx "staff +0.05 +0.00 +0.00 +0.00" "$work/late.out" ||
  fail "late: the late answer was typed as keys: $(grep '^staff' "$work/late.out")"

# No pixels in TIOCGWINSZ: the cell size from CSI 16 t (a whole 504x270 picture), else characters.
run csi16 1
grep -q '^notice' "$work/csi16.out" && fail "csi16: a fallback line: $(cat "$work/csi16.out")"
grep -q '^pictures .*[0-9]' "$work/csi16.out" || fail "csi16: no picture: $(cat "$work/csi16.out")"
run nocell 1
grep -qF "notice pixels off: the terminal gave no cell size in pixels (TIOCGWINSZ, CSI 16 t)" "$work/nocell.out" ||
  fail "nocell: no fallback line: $(cat "$work/nocell.out")"

run nopixel 1
grep -qF "notice pixels off: no sixel or kitty graphics in this terminal (xterm: -ti vt340)" "$work/nopixel.out" ||
  fail "nopixel: no fallback line: $(cat "$work/nopixel.out")"

run sixel 3
grep -q '^notice' "$work/sixel.out" && fail "sixel: a fallback line: $(cat "$work/sixel.out")"
read -r _ _ whole _ < <(grep '^first-screen' "$work/sixel.out")
[ "$whole" -gt 1000 ] || fail "sixel: no whole picture on the first path screen: $(cat "$work/sixel.out")"
while read -r _ key _ band; do
  [ "$band" -gt 0 ] && [ "$band" -lt "$whole" ] ||
    fail "sixel: staff key $key sent $band picture bytes (the whole picture is $whole)"
done < <(grep '^key' "$work/sixel.out")
read -r _ _ redrawn _ < <(grep '^redraw' "$work/sixel.out")
[ "$redrawn" -gt 1000 ] || fail "sixel: Ctrl-L did not send the whole picture again: $(cat "$work/sixel.out")"
# 100x30 cells of 9x15: 23 cell rows of 15 (345, sent as 348) and 622 pixels across in 70 cells.
read -r _ _ resized size < <(grep '^resize' "$work/sixel.out")
[ "$resized" -gt 1000 ] && [ "$size" = 630x348 ] ||
  fail "sixel: after a resize to 100x30 the picture is $size ($resized bytes), not 630x348"
echo "passed: silent, late, cell-size-less and sixel-less terminals fall back with why, CSI 16 t gives the cell; sixel: whole picture $redrawn bytes (Ctrl-L)," \
  "staff keys $(grep '^key' "$work/sixel.out" | awk '{print $4}' | paste -sd' ') bytes of picture, 100x30 $resized"
