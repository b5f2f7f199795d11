#!/usr/bin/env bash
# End-to-end at 80x24, the size terminal emulators and SSH clients open with (issue 12, SPEC §1,
# §3, §7.2, §7.3): the session starts; the default glyphs follow the locale and TERM; TERM=dumb and
# a glyph set the locale cannot show are refused; Esc and escape sequences on a slow link; Ctrl-L.
# Usage: tmux_80x24.sh APCS DATA_FOLDER [core|help-and-quit]
#   core           (default) what the terminal shell and the command line do
#   help-and-quit  the help screen (? and F1) and the quit questions (q, Esc on an empty prompt)
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
part=${3:-core}
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder 80x24
cp "$data"/key1.dat "$data"/key2.dat "$data"/way1.dat "$work"/

start() { start_80x24 "$@"; }
keys() { keys_to "$@"; }
# Bytes sent as they are, no pause after.
bytes() { tmux -L "$socket" send-keys -t "$1" -l "$2"; }
fail() { fail_showing "$@"; }
# The screen of session $1 with wrapped lines joined, for messages longer than 80 columns.
joined() { tmux -L "$socket" capture-pane -p -J -t "$1"; }
# Line $2 (1-based) of session $1's screen.
line() { screen "$1" | sed -n "$2p"; }
# Whether the screen of session $1 holds a braille character (U+2800-U+28FF: E2 A0 80 to E2 A3 BF).
has_braille() { screen "$1" | LC_ALL=C grep -q $'\xe2[\xa0-\xa3]'; }

# Up to the 8/2 choice of graphics mode with the shipped way1.dat: the keyboard takes over there.
printf 'ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n' > "$work/graphics.keys"
local_message="Local: 4/6 move the arrow, Enter picks the FIRST control point"
passed=0

if [ "$part" = core ]; then
  # --- 80x24 is enough: the session starts, no "must be at least".
  start text "LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs'"
  wait_for text "Please keyin the KEY1 filename!"
  screen text | grep -q "must be at least" && fail "80x24 was refused" text
  passed=$((passed + 1))

  # --- At a text prompt an Esc quickly followed by an arrow, in either cursor-key mode, and
  # sequences APCS does not know (Ctrl-Left, F5, bracketed paste) type nothing. Each Esc meets a
  # typed line, which it clears (on an empty line it would ask to quit: help-and-quit's part).
  empty_prompt() { [ "$(line text 2)" = "_" ] || fail "$1 typed '$(line text 2)' at the prompt" text; }
  bytes text 'x'
  bytes text $'\e\e[D'
  sleep 0.3
  empty_prompt "Esc (clearing x) and ESC [ D in one write"
  bytes text 'abc'
  bytes text $'\e'
  sleep 0.01
  bytes text $'\eOD'
  sleep 0.3
  empty_prompt "Esc (clearing abc) and ESC O D 10 ms later"
  # ESC, then [C 60 ms later, inside the default ESCDELAY of 100 ms. A loaded machine (CI runs two
  # suites at once) can stretch the gap past 100 ms, when the Esc alone rightly asks to quit: then
  # the question is answered N and the pair sent again, three tries in all. A program that does not
  # wait for the rest of the sequence asks to quit every time.
  for try in 1 2 3; do
    bytes text $'\e'
    sleep 0.06
    bytes text '[C'
    sleep 0.3
    line text 2 | grep -q "^Quit APCS" || break
    [ "$try" -lt 3 ] || fail "ESC and [C 60 ms later asked to quit three times" text
    keys text n
  done
  empty_prompt "ESC and [C 60 ms later"
  bytes text $'\e[1;5D\e[15~\e[200~'
  sleep 0.3
  empty_prompt "unknown escape sequences"
  bytes text 'key1.dat'
  sleep 0.3
  [ "$(line text 2)" = "key1.dat_" ] || fail "stray characters typed at the prompt: '$(line text 2)'" text
  keys text Enter
  wait_for text "Please keyin the KEY2 filename!"
  passed=$((passed + 1))

  # --- The default glyphs of a UTF-8 locale on a terminal that shows braille: braille.
  start braille "ESCDELAY=400 LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --keys graphics.keys --record braille.keys"
  wait_for braille "8 : Global Control"
  has_braille braille || fail "no braille in a UTF-8 locale on TERM=$(tmux -L "$socket" show -gv default-terminal)" braille
  passed=$((passed + 1))

  # --- ESC, then 60 ms later [D, at the local-control arrow is the left arrow, not Esc: the arrow
  # moves back one control point and the step stays. This session's ESCDELAY is the environment's
  # 400 ms (so a loaded machine cannot stretch 60 ms past it); the default 100 ms is tried above.
  keys braille 2
  wait_for braille "$local_message"
  keys braille 6 6
  after_two=$(screen braille)
  keys braille 6
  [ "$(screen braille)" != "$after_two" ] || fail "the arrow did not move with 6" braille
  bytes braille $'\e'
  sleep 0.06
  bytes braille '[D'
  sleep 0.3
  screen braille | grep -qF "$local_message" || fail "ESC and [D 60 ms later were taken as Esc" braille
  [ "$(screen braille)" = "$after_two" ] || fail "ESC and [D 60 ms later did not move the arrow left" braille
  passed=$((passed + 1))

  # --- Ctrl-L repaints a screen garbled from outside, and reaches the session's record.
  intact=$(screen braille)
  printf '\033[2J\033[5;5HGARBLED' > "$(tmux -L "$socket" display -p -t braille '#{pane_tty}')"
  sleep 0.2
  screen braille | grep -q GARBLED || fail "the screen could not be garbled for the test" braille
  keys braille C-l
  sleep 0.2
  [ "$(screen braille)" = "$intact" ] || fail "Ctrl-L did not redraw the screen" braille
  # --- A cell whose style alone changes is sent again: the control point picked, its 'x' the
  # same character, shows in reverse video (SPEC 7.2).
  styled() { tmux -L "$socket" capture-pane -p -e -t "$1"; }
  # With colour (--color auto) a region's x is also in the region's colour: \e[7m\e[95mx.
  reversed_x() { styled braille | grep -qE $'\e\\[7m(\e\\[[0-9;]*m)*x'; }
  reversed_x && fail "a control point in reverse video before any pick" braille
  keys braille Enter
  reversed_x || fail "the picked control point is not shown in reverse video" braille
  tmux -L "$socket" kill-session -t braille
  for _ in $(seq 1 50); do [ -s "$work/braille.keys" ] && break; sleep 0.1; done
  grep -qw "CTRL-L" "$work/braille.keys" || { echo "Ctrl-L not recorded:"; cat "$work/braille.keys"; exit 1; }
  passed=$((passed + 1))

  # --- The Linux console cannot show braille: TERM=linux in a UTF-8 locale draws ascii.
  start console "TERM=linux LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --keys graphics.keys"
  wait_for console "8 : Global Control"
  has_braille console && fail "braille on TERM=linux without --glyphs" console
  passed=$((passed + 1))

  # --- TERM=dumb is a terminal problem: exit 3, one line.
  start dumb "TERM=dumb '$apcs'"
  wait_for dumb "EXITED=3"
  joined dumb | grep -q "^apcs: the terminal type 'dumb' cannot show a full screen" || fail "no message for TERM=dumb" dumb
  passed=$((passed + 1))

  # --- A glyph set the locale cannot show is refused: exit 2, one line, the terminal untouched.
  start c_braille "env -u LC_ALL -u LC_CTYPE LANG=C '$apcs' --glyphs braille"
  wait_for c_braille "EXITED=2"
  joined c_braille | grep -qxF "apcs: --glyphs braille needs a UTF-8 locale (LANG=C.UTF-8 or similar); use --glyphs ascii" ||
    fail "no message for LANG=C --glyphs braille" c_braille
  start c_blocks "LC_ALL=C '$apcs' --glyphs blocks"
  wait_for c_blocks "EXITED=2"
  joined c_blocks | grep -qF "apcs: --glyphs blocks needs a UTF-8 locale" || fail "no message for LC_ALL=C --glyphs blocks" c_blocks
  # ascii needs no UTF-8.
  start c_ascii "LC_ALL=C '$apcs' --glyphs ascii"
  wait_for c_ascii "Please keyin the KEY1 filename!"
  passed=$((passed + 1))

elif [ "$part" = help-and-quit ]; then
  # =================================================================================
  # The help screen and the quit prompt (issue 12, SPEC §7.3). These are the session's (key map,
  # screens); this part fails until the session has them.
  # =================================================================================

  # --- ? in graphics mode shows a help screen of the step's keys; any key closes it.
  start help "LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --glyphs ascii --keys graphics.keys"
  wait_for help "8 : Global Control"
  graphics=$(screen help)
  keys help '?'
  [ "$(screen help)" != "$graphics" ] || fail "? shows no help screen" help
  screen help | grep -qi "global control" || fail "the help screen does not list the step's keys (Global Control)" help
  screen help | grep -qi "local control" || fail "the help screen does not list the step's keys (Local Control)" help
  keys help Space
  [ "$(screen help)" = "$graphics" ] || fail "a key did not close the help screen" help
  # --- F1 too.
  keys help F1
  [ "$(screen help)" != "$graphics" ] || fail "F1 shows no help screen" help
  keys help x
  [ "$(screen help)" = "$graphics" ] || fail "a key did not close the help screen (F1)" help
  passed=$((passed + 1))

  # --- q asks; Enter means N and the step goes on; q then Y ends with exit 0, files listed.
  keys help q
  wait_for help "Quit without saving this path ? (Y/N)"
  keys help Enter
  screen help | grep -qF "Quit without saving this path ? (Y/N)" && fail "Enter did not answer N" help
  screen help | grep -q "8 : Global Control" || fail "after N the 8/2 choice is gone" help
  keys help q
  wait_for help "Quit without saving this path ? (Y/N)"
  keys help Y
  wait_for help "EXITED=0"
  screen help | grep -q "^ani1.dat$" || fail "the files written so far are not listed" help
  passed=$((passed + 1))

  # --- At a text prompt q is typed text, and F1 shows the help, which names the answer an empty
  # line takes at that prompt (SPEC §7.3); the prompt's own rows come back unchanged.
  start prompt "LANG=C.UTF-8 LC_ALL=C.UTF-8 '$apcs' --glyphs ascii"
  wait_for prompt "Please keyin the KEY1 filename!"
  keys prompt q
  [ "$(line prompt 2)" = "q_" ] || fail "q at a text prompt is not typed: '$(line prompt 2)'" prompt
  keys prompt BSpace
  prompt_screen=$(screen prompt)
  keys prompt F1
  [ "$(screen prompt)" != "$prompt_screen" ] || fail "F1 at a text prompt shows no help" prompt
  screen prompt | grep -qF "an empty line takes key1.dat" || fail "the help does not name key1.dat" prompt
  keys prompt Space
  [ "$(screen prompt)" = "$prompt_screen" ] || fail "a key did not close the help at a text prompt" prompt
  keys prompt Enter
  wait_for prompt "Please keyin the KEY2 filename!"
  keys prompt F1
  screen prompt | grep -qF "an empty line takes key2.dat" || fail "the help at KEY2 does not name key2.dat" prompt
  keys prompt Space
  passed=$((passed + 1))

  # --- Esc on an empty prompt asks "Quit APCS ? (Y/N)" on the answer's row; N and Esc go back to
  # the prompt as it was; Esc on a typed line clears it; Y ends with exit 0, as q does.
  prompt_screen=$(screen prompt)
  keys prompt Escape
  [ "$(line prompt 4)" = "Quit APCS ? (Y/N)_" ] || fail "Esc on an empty line did not ask to quit" prompt
  keys prompt n
  [ "$(screen prompt)" = "$prompt_screen" ] || fail "N did not go back to the prompt as it was" prompt
  keys prompt Escape
  keys prompt Escape
  [ "$(screen prompt)" = "$prompt_screen" ] || fail "Esc did not answer N" prompt
  keys prompt a b c
  keys prompt Escape
  [ "$(screen prompt)" = "$prompt_screen" ] || fail "Esc did not clear a typed line" prompt
  keys prompt Escape
  wait_for prompt "Quit APCS ? (Y/N)"
  keys prompt y
  wait_for prompt "EXITED=0"
  passed=$((passed + 1))
else
  echo "unknown part '$part' (core or help-and-quit)"; exit 2
fi
echo "$passed passed, 0 failed"
