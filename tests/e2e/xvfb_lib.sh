# Helpers for the tests that run a real terminal on a virtual X server; source it.

# As in tmux_lib.sh: the terminal's end hangs up the programs in it, and an ASan build's leak check
# caught by that hang-up can spin for good; leaks are the unit tests' business.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
source "$(dirname "${BASH_SOURCE[0]}")/ended_lib.sh"

# Skips the test (exit 77) unless every tool named is installed; $1 is the terminal's name, for the
# message.
xvfb_needs() {
  local terminal_name=$1 tool
  for tool in Xvfb "$@" xwd convert python3; do
    command -v "$tool" > /dev/null || { echo "skipped: no $tool (xvfb, $terminal_name, x11-apps, imagemagick)"; exit 77; }
  done
}

# A fresh work folder ($work), removed at the end with the X server ($server) and the terminal
# ($terminal: set it to the terminal's pid), both ended by their pids.
xvfb_test_folder() {
  work=$(mktemp -d)
  server=""
  terminal=""
  trap '[ -n "$terminal" ] && kill "$terminal" 2> /dev/null; [ -n "$server" ] && kill "$server" 2> /dev/null; all_ended_in "$work"; rm -rf "$work"' EXIT
}

# Starts Xvfb at 1024x768 (or WIDTHxHEIGHT, $1) on a display of its choosing and exports DISPLAY;
# skips the test (exit 77) where it cannot start. $xvfb_width is the screen's width.
xvfb_start() {
  local size=${1:-1024x768}
  xvfb_width=${size%x*}
  Xvfb -displayfd 3 -screen 0 "${size}x24" -nolisten tcp 3> "$work/display" 2> "$work/xvfb.log" &
  server=$!
  for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
  [ -s "$work/display" ] || { echo "skipped: Xvfb did not start: $(tail -1 "$work/xvfb.log")"; exit 77; }
  export DISPLAY=":$(cat "$work/display")"
}

# Polls the screen, TRIES times every 0.5 s, for PICTURE (8-bit grey, WIDTH wide) pixel for pixel
# within 10 pixels of its top-left corner (find_picture.py); what it found is in $work/found, the
# last screenshot in $work/screen.xwd.
xvfb_find_picture() {
  local picture=$1 width=$2 tries=$3
  : > "$work/found"
  for _ in $(seq "$tries"); do
    sleep 0.5
    xwd -root -silent > "$work/screen.xwd" 2> /dev/null || continue
    convert "xwd:$work/screen.xwd" -colorspace gray -depth 8 "gray:$work/screen.grey" 2> /dev/null || continue
    python3 "$here/find_picture.py" "$work/screen.grey" "$xvfb_width" "$picture" "$width" 10 > "$work/found" && break
  done
}
