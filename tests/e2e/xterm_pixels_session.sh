#!/usr/bin/env bash
# The session with --pixels auto in a real xterm started as a VT340 (xterm 379, Debian 12's, sixel
# built in) at 80x24 with the 9x15 font, on a virtual X server (Xvfb): the terminal answers the
# questions of --pixels (device attributes with 4, no kitty reply, the cell size in TIOCGWINSZ),
# the path screen comes as a sixel picture, six staff keys each send only the changed band, and a
# screenshot (xwd, converted by ImageMagick) holds, pixel for pixel, the picture worked out apart
# (pixel_oracle.py) from the monitor's picture of the same screen (--handout's PNG).
# Usage: xterm_pixels_session.sh APCS DATA_FOLDER (skips, exit 77, without Xvfb, xterm, xwd,
# ImageMagick's convert or python3, or where Xvfb cannot start).
set -uo pipefail
apcs=$1
data=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb_lib.sh"
xvfb_needs xterm
xvfb_test_folder
fail() { echo "FAILED: $*"; exit 1; }

mkdir "$work/session"
cp "$data/n-to-l/key1.dat" "$data/n-to-l/key2.dat" "$data/n-to-l/way1.dat" "$work/session/"
# To the path screen's staff (global control), six tension steps, a caption for --handout.
printf 'ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n8\n6\n6\n6\n6\n6\n6\n;; six tension steps\n' \
  > "$work/staff.keys"
xvfb_start
# --pace 300: each staff key is its own screen, sent as a band after the whole first picture.
xterm -ti vt340 -fn 9x15 -geometry 80x24+0+0 -e sh -c "cd '$work/session' && LANG=C.UTF-8 '$apcs' --glyphs ascii \
  --pixels auto --keys '$work/staff.keys' --pace 300 --handout '$work/handout' 2> '$work/stderr'; sleep 60" &
terminal=$!
for _ in $(seq 100); do [ -s "$work/handout/01-six-tension-steps.png" ] && break; sleep 0.2; done
[ -s "$work/handout/01-six-tension-steps.png" ] || fail "the replay did not reach its caption: $(cat "$work/stderr")"
convert "$work/handout/01-six-tension-steps.png" -colorspace gray -depth 8 "gray:$work/monitor.grey" ||
  fail "convert the handout's PNG"
python3 "$here/pixel_oracle.py" "$work/monitor.grey" 9 15 80 24 255 "$work/expected.grey" > "$work/oracle" ||
  fail "pixel_oracle.py"
# The drawing area begins where the terminal's text does (its border, a few pixels in).
for _ in $(seq 20); do
  sleep 0.5
  xwd -root -silent > "$work/screen.xwd" 2> /dev/null || continue
  convert "xwd:$work/screen.xwd" -colorspace gray -depth 8 "gray:$work/screen.grey" 2> /dev/null || continue
  python3 "$here/find_picture.py" "$work/screen.grey" 1024 "$work/expected.grey" 720 10 > "$work/found" && break
done
if ! grep -q "^at " "$work/found"; then
  convert "xwd:$work/screen.xwd" "${TMPDIR:-/tmp}/xterm_pixels_session.png" 2> /dev/null
  fail "xterm does not show the $(cat "$work/oracle") of the path screen: $(cat "$work/found")" \
    "(screenshot: ${TMPDIR:-/tmp}/xterm_pixels_session.png)"
fi
echo "passed: xterm -ti vt340 shows the path screen's $(cat "$work/oracle") $(cat "$work/found")"
