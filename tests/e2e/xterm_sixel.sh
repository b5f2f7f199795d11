#!/usr/bin/env bash
# A --sixel file shown by a real terminal: xterm 379 (Debian 12's, sixel built in) started as a
# VT340 under Xvfb, `cat FILE` in it, a screenshot (xwd): the picture's 720x522 pixels are on the
# screen exactly, black ones painted black on xterm's white background (not left transparent).
# Usage: xterm_sixel.sh APCS DATA_FOLDER (skips, exit 77, without Xvfb, xterm, xwd, ImageMagick's
# convert or python3, or where Xvfb cannot start).
set -uo pipefail
apcs=$1
data=$2
for tool in Xvfb xterm xwd convert python3; do
  command -v "$tool" > /dev/null || { echo "skipped: no $tool (xvfb, xterm, x11-apps, imagemagick)"; exit 77; }
done
work=$(mktemp -d)
server=""
cleanup() { [ -n "$server" ] && kill "$server" 2> /dev/null; rm -rf "$work"; }
trap cleanup EXIT
fail() { echo "FAILED: $*"; exit 1; }

"$apcs" path "$data/n-to-l/way1.dat" --tension 0.5 --sixel "$work/way1.six" --png "$work/way1.png" ||
  fail "apcs path --sixel"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3> "$work/display" 2> "$work/xvfb.log" &
server=$!
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || { echo "skipped: Xvfb did not start: $(tail -1 "$work/xvfb.log")"; exit 77; }
export DISPLAY=":$(cat "$work/display")"
xterm -ti vt340 -fn 9x15 -geometry 100x45+0+0 -e sh -c "cat '$work/way1.six'; sleep 30" &
terminal=$!
convert "$work/way1.png" -colorspace gray -depth 8 "gray:$work/picture.grey" || fail "convert way1.png"
# The picture is where xterm's text begins (its border, a few pixels in); polled until it is there.
for _ in $(seq 40); do
  sleep 0.5
  xwd -root -silent > "$work/screen.xwd" 2> /dev/null || continue
  convert "xwd:$work/screen.xwd" -colorspace gray -depth 8 "gray:$work/screen.grey" 2> /dev/null || continue
  python3 - "$work/screen.grey" "$work/picture.grey" > "$work/found" << 'PYTHON' && break
import sys
screen, picture = open(sys.argv[1], "rb").read(), open(sys.argv[2], "rb").read()
width, rows, screen_width = 720, 522, 1024
for top in range(8):
    for left in range(8):
        if all(screen[(top + y) * screen_width + left:(top + y) * screen_width + left + width] ==
               picture[y * width:(y + 1) * width] for y in range(rows)):
            print(f"at +{left}+{top}: all {width}x{rows} pixels, {sum(1 for v in picture if v)} lit")
            sys.exit(0)
sys.exit(1)
PYTHON
done
kill "$terminal" 2> /dev/null
[ -s "$work/found" ] || fail "the sixel picture is not on xterm's screen pixel for pixel"
echo "passed: xterm -ti vt340 shows way1.six $(cat "$work/found")"
