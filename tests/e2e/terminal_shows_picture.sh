#!/usr/bin/env bash
# A picture file shown by a real terminal on a virtual X server (Xvfb), `cat FILE` in it, a
# screenshot (xwd): the picture's 720x522 pixels are on the screen exactly, black ones black on the
# terminal's white background (painted, not left transparent or half opaque).
#   xterm: apcs path --sixel, in xterm 379 (Debian 12's, sixel built in) started as a VT340;
#   kitty: apcs path --kitty, in kitty 0.26 (software OpenGL), whose 11-point cells are 9x18 pixels
#          here, so that the picture's 80x29 cells are its 720x522 pixels unscaled; in a window of
#          100x40 cells (its default window, 80x24 cells here, scrolled the picture's top away).
# Usage: terminal_shows_picture.sh APCS DATA_FOLDER xterm|kitty (skips, exit 77, without Xvfb, the
# terminal, xwd, ImageMagick's convert or python3, or where Xvfb cannot start).
set -uo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
terminal_name=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb_lib.sh"
xvfb_needs "$terminal_name"
xvfb_test_folder
fail() { echo "FAILED: $*"; exit 1; }

case $terminal_name in
  xterm) option=--sixel file=$work/way1.six ;;
  kitty) option=--kitty file=$work/way1.kitty ;;
  *) fail "no terminal $terminal_name" ;;
esac
"$apcs" path "$data/n-to-l/way1.dat" --tension 0.5 "$option" "$file" --png "$work/way1.png" || fail "apcs path $option"
convert "$work/way1.png" -colorspace gray -depth 8 "gray:$work/picture.grey" || fail "convert way1.png"
xvfb_start
case $terminal_name in
  xterm) xterm -ti vt340 -fn 9x15 -geometry 100x45+0+0 -e sh -c "cat '$file'; sleep 60" & ;;
  # kitty opens 80x24 cells (or the size it remembered) unless told: too small for the picture.
  kitty) LIBGL_ALWAYS_SOFTWARE=1 kitty --config NONE -o background=#ffffff -o foreground=#000000 -o font_size=11 \
           -o initial_window_width=100c -o initial_window_height=40c -o remember_window_size=no \
           sh -c "cat '$file'; sleep 60" > "$work/kitty.log" 2>&1 & ;;
esac
terminal=$!
# The picture is where the terminal's text begins (its border, a few pixels in); polled until there:
# up to 100 looks, a minute or more (kitty drawing with software OpenGL beside CI's two builds once
# showed it only in part after 40 looks, 32 s; alone it shows it in 2 s).
xvfb_find_picture "$work/picture.grey" 720 100
grep -q "^at " "$work/found" || fail "$terminal_name does not show the picture pixel for pixel: $(cat "$work/found")"
echo "passed: $terminal_name shows apcs path $option's file $(cat "$work/found")"
