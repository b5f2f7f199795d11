#!/usr/bin/env bash
# End-to-end colour (SPEC §7.2.1): in a terminal with colour the tangent arrows (T) are drawn in a
# colour of their own, not the curve's (the terminal's default foreground); NO_COLOR=1 and
# --color never send no colour at all. tmux keeps each cell's colour: capture-pane -e shows it as
# SGR sequences.
# Usage: tmux_colour.sh APCS DATA_FOLDER
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }
command -v python3 >/dev/null || { echo "python3 is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder colour
cp "$data"/key1.dat "$data"/key2.dat "$data"/way1.dat "$work"/
# Up to the staff of global control with way1.dat, then T.
printf 'ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n' > "$work/graphics.keys"

# The foreground colours (SGR) of the cells of session $1 holding a tangent arrow's head (> < v in
# ascii, where ^ is a line glyph of the curve too; arrows elsewhere) and of the boundary's top-left corner (the monitor's colour), as
# "HEAD_COLOURS|CORNER_COLOUR".
colours_of() {
  tmux -L "$socket" capture-pane -e -p -t "$1" | python3 -c '
import re, sys
plus, corner = set(), None
for row, line in enumerate(sys.stdin.read().split("\n")[:17]):
    fg, column = "default", 0
    for token in re.findall(r"\x1b\[[0-9;]*m|[^\x1b]", line):
        if token.startswith("\x1b"):
            codes = token[2:-1].split(";") if token[2:-1] else ["0"]
            i = 0
            while i < len(codes):
                c = codes[i]
                if c in ("0", "39"): fg = "default"
                elif len(c) == 2 and c[0] == "3" and c[1] in "01234567": fg = c
                elif c == "38" and i + 2 < len(codes) and codes[i + 1] == "5": fg = "38;5;" + codes[i + 2]; i += 2
                i += 1
            continue
        if token in "><v\u2190\u2191\u2192\u2193\u2196\u2197\u2198\u2199\u21d0\u21d1\u21d2\u21d3\u21d6\u21d7\u21d8\u21d9" and row > 0: plus.add(fg)
        if row == 0 and column == 0: corner = fg
        column += 1
print(",".join(sorted(plus)) + "|" + str(corner))'
}
# Whether session $1's screen holds a colour SGR (foreground or background, 8, 256 or true colour).
has_colour_sgr() { tmux -L "$socket" capture-pane -e -p -t "$1" | grep -qE $'\e\\[([0-9;]*;)?(3[0-8]|4[0-8]|9[0-7]|10[0-7])[;m]'; }

passed=0
for glyphs in braille ascii; do
  start_80x24 "colour-$glyphs" "TERM=xterm-256color LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --glyphs $glyphs --keys graphics.keys"
  sleep 1.5
  keys_to "colour-$glyphs" 8
  keys_to "colour-$glyphs" T
  wait_for "colour-$glyphs" "DS "
  seen=$(colours_of "colour-$glyphs")
  plus=${seen%|*}
  corner=${seen#*|}
  [ -n "$plus" ] || fail_showing "$glyphs: no tangent arrow head on the screen" "colour-$glyphs"
  [ "$corner" = default ] || fail_showing "$glyphs: the boundary is in $corner, not the monitor's colour" "colour-$glyphs"
  case ",$plus," in *,default,*) fail_showing "$glyphs: a tangent arrow head is in the curve's colour ($plus)" "colour-$glyphs" ;; esac
  heads_in_colour=$plus
  passed=$((passed + 1))
done

# A terminal whose terminfo gives colours but no way back to its own (no op, no oc): ncurses'
# use_default_colors fails there, and the roles' pairs on the default background (-1) with it (the
# arrows were then drawn in an unmade pair: black, on black). They keep their colour, on black.
command -v tic >/dev/null || { echo "tic is not installed (ncurses-bin)"; exit 77; }
mkdir "$work/terminfo"
infocmp -1 -x xterm-256color | grep -vE '^\s*(op|oc)=' |
  sed '1,/^xterm-256color|/s/^xterm-256color|.*/xterm-no-default|xterm-256color with no default colours,/' > "$work/no-default.src"
tic -x -o "$work/terminfo" "$work/no-default.src"
start_80x24 no-default "TERMINFO='$work/terminfo' TERM=xterm-no-default LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --glyphs ascii --keys graphics.keys"
sleep 1.5
keys_to no-default 8
keys_to no-default T
wait_for no-default "DS "
seen=$(colours_of no-default)
plus=${seen%|*}
[ -n "$plus" ] || fail_showing "no default colours: no tangent arrow head on the screen" no-default
[ "$plus" = "$heads_in_colour" ] ||
  fail_showing "no default colours: the tangent arrow heads are in $plus, not $heads_in_colour as in xterm-256color" no-default
passed=$((passed + 1))

for how in "NO_COLOR=1 '$apcs'" "'$apcs' --color never"; do
  name="mono-$passed"
  start_80x24 "$name" "TERM=xterm-256color LANG=C.UTF-8 LC_ALL=C.UTF-8 $how --keys graphics.keys"
  sleep 1.5
  keys_to "$name" 8
  keys_to "$name" T
  wait_for "$name" "DS "
  ! has_colour_sgr "$name" || fail_showing "$how sent colour" "$name"
  passed=$((passed + 1))
done
echo "passed: $passed checks"
