#!/usr/bin/env bash
# The session with --pixels auto in a real terminal on a virtual X server (Xvfb), at 80x24: the
# terminal answers the questions of --pixels itself, the path screen comes as a picture, six staff
# keys each send only the changed band, and a screenshot (xwd, converted by ImageMagick) holds,
# pixel for pixel, the picture worked out apart (pixel_oracle.py) from the monitor's picture of the
# same screen (--handout's PNG) at the cell size the terminal gives (TIOCGWINSZ, read in it).
#   xterm: xterm 379 (Debian 12's, sixel built in) started as a VT340 with the 9x15 font: device
#          attributes with 4, no kitty reply: sixel, which is all xterm shows;
#   xterm-wide: the same xterm at 170x55 (1530x825 pixels): the picture unlimited would be 1053
#          pixels across, beyond the 1000 xterm shows (it would show nothing); it keeps within the
#          limit xterm gives (XTSMGRAPHICS, asked in it too).
#   kitty: kitty 0.26 (software OpenGL), 11-point cells: it answers the kitty query: the kitty
#          graphics protocol, which is all kitty shows.
# Usage: terminal_pixels_session.sh APCS DATA_FOLDER xterm|xterm-wide|kitty (skips, exit 77, without Xvfb,
# the terminal, xwd, ImageMagick's convert or python3, or where Xvfb cannot start).
set -uo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
terminal_name=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb_lib.sh"
xvfb_needs "${terminal_name%-wide}"
xvfb_test_folder
fail() { echo "FAILED: $*"; exit 1; }

mkdir "$work/session"
cp "$data/n-to-l/key1.dat" "$data/n-to-l/key2.dat" "$data/n-to-l/way1.dat" "$work/session/"
# To the path screen's staff (global control), six tension steps, a caption for --handout.
printf 'ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n8\n6\n6\n6\n6\n6\n6\n;; six tension steps\n' \
  > "$work/staff.keys"
# In the terminal: its size in cells and pixels, then the session. --pace 300: each staff key is a
# screen of its own, sent as a band after the first whole picture.
cat > "$work/run.sh" <<RUN
cd '$work/session'
python3 -c 'import fcntl, struct, termios; print(*struct.unpack("HHHH", fcntl.ioctl(0, termios.TIOCGWINSZ, bytes(8))))' \
  > '$work/size'
python3 '$here/sixel_limit.py' > '$work/limit'
LANG=C.UTF-8 '$apcs' --glyphs ascii --pixels auto --keys '$work/staff.keys' --pace 300 --handout '$work/handout' \
  2> '$work/stderr'
sleep 60
RUN
case $terminal_name in
  xterm-wide) xvfb_start 1600x900 ;;
  *) xvfb_start ;;
esac
case $terminal_name in
  xterm) xterm -ti vt340 -fn 9x15 -geometry 80x24+0+0 -e sh "$work/run.sh" & ;;
  xterm-wide) xterm -ti vt340 -fn 9x15 -geometry 170x55+0+0 -e sh "$work/run.sh" & ;;
  kitty) LIBGL_ALWAYS_SOFTWARE=1 kitty --config NONE -o background=#ffffff -o foreground=#000000 -o font_size=11 \
           -o initial_window_width=80c -o initial_window_height=24c -o remember_window_size=no \
           sh "$work/run.sh" > "$work/kitty.log" 2>&1 & ;;
  *) fail "no terminal $terminal_name" ;;
esac
terminal=$!
handout=$work/handout/01-six-tension-steps.png
for _ in $(seq 100); do [ -s "$handout" ] && break; sleep 0.2; done
[ -s "$handout" ] || fail "the replay did not reach its caption: $(cat "$work/stderr")"
read -r rows columns pixel_width pixel_height < "$work/size" || fail "no window size from $terminal_name"
[ "$pixel_width" -gt 0 ] || fail "$terminal_name gives no pixel size in TIOCGWINSZ"
cell_width=$((pixel_width / columns))
cell_height=$((pixel_height / rows))
convert "$handout" -colorspace gray -depth 8 "gray:$work/monitor.grey" || fail "convert the handout's PNG"
read -r limit_width limit_height < "$work/limit" || fail "no answer from sixel_limit.py"
python3 "$here/pixel_oracle.py" "$work/monitor.grey" "$cell_width" "$cell_height" "$columns" "$rows" 255 \
  "$work/expected.grey" "$limit_width" "$limit_height" > "$work/oracle" || fail "pixel_oracle.py"
# The drawing area begins where the terminal's text does (its border, a few pixels in).
xvfb_find_picture "$work/expected.grey" $((columns * cell_width)) 20
if ! grep -q "^at " "$work/found"; then
  convert "xwd:$work/screen.xwd" "${TMPDIR:-/tmp}/${terminal_name}_pixels_session.png" 2> /dev/null
  fail "$terminal_name (${columns}x$rows cells of ${cell_width}x$cell_height) does not show the" \
    "$(cat "$work/oracle") of the path screen: $(cat "$work/found")" \
    "(screenshot: ${TMPDIR:-/tmp}/${terminal_name}_pixels_session.png)"
fi
echo "passed: $terminal_name (${columns}x$rows cells of ${cell_width}x$cell_height) shows the path screen's" \
  "$(cat "$work/oracle") $(cat "$work/found")"
