#!/usr/bin/env bash
# The slide-deck keys and compare (SPEC 3.1) on a large screen: the continuity lesson at 200x60 in
# ascii, driven with PgDn, PgUp and Home as a presenter's remote would; C's reference A (its label
# on the top edge, its letter on the curve) shown beside the live curve, and unpinned by C.
# Usage: tmux_deck_200x60.sh APCS DATA_FOLDER
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder deck200
cp "$data"/key1.dat "$data"/key2.dat "$data"/way1.dat "$data"/lesson-continuity.keys "$work"/
fail() { fail_showing "$@"; }
# Polls up to 5 s for a screen of session deck that COMMAND (reading the screen) accepts: the badge
# may be painted before the rest of a large screen.
eventually() { for _ in $(seq 1 50); do screen deck | eval "$1" && return 0; sleep 0.1; done; return 1; }
keys() { keys_to "$@"; }

tmux -L "$socket" new-session -d -s deck -x 200 -y 60 -c "$work" \
  "LANG=C.UTF-8 $apcs --keys lesson-continuity.keys --pace step --glyphs ascii; echo EXITED=\$?; sleep 60"
[ "$(tmux -L "$socket" display -p -t deck '#{pane_width}x#{pane_height}')" = 200x60 ] || fail "the pane is not 200x60"

captions=$(grep -c '^;;' "$work/lesson-continuity.keys")
caption_number() { grep '^;;' "$work/lesson-continuity.keys" | grep -n -- "$1" | cut -d: -f1; }
pin=$(caption_number "C pins")
wait_for deck "caption 0 of $captions"
keys deck NPage
wait_for deck "key PGDN | caption 1 of $captions"
# The caption is under the staff, the badge on the top row, at 200 columns as at 80.
screen deck | grep -v "^ *$" | tail -n 1 | grep -q "T shows the tangents" || fail "the first caption is not under the staff" deck
for n in $(seq 2 "$captions"); do
  keys deck NPage
  wait_for deck "key PGDN | caption $n of $captions"
  if [ "$n" -lt "$pin" ]; then
    screen deck | head -n 2 | grep -q "A: continuity" && fail "a reference is shown before C pinned one" deck
  fi
done
# The label's 80x24 cell row is the top edge's; 60 rows put it just under the edge, clear of the curve.
eventually 'sed -n 2p | grep -q -E -- "^\| +A: continuity -1\.00 "' || fail "reference A's label is not under the top edge" deck
# The letter A on the curve where -1's corner runs apart from +1's spike (not the label's A).
eventually "sed -n '3,45p' | grep -q A" || fail "no letter A on the pinned curve" deck
keys deck PPage
wait_for deck "key PGUP | caption $((captions - 1)) of $captions"
eventually 'head -n 2 | grep -q -- "A: continuity -1.00"' || fail "going back lost reference A" deck
keys deck Home
wait_for deck "key HOME | caption 1 of $captions"
screen deck | head -n 2 | grep -q "A: continuity" && fail "Home kept a reference pinned later" deck
for _ in $(seq 2 "$captions"); do keys deck NPage; done
wait_for deck "key PGDN | caption $captions of $captions"
keys deck NPage
wait_for deck "End of the script"
# The keyboard is the class's: C unpins A.
keys deck C
wait_for deck "reference A unpinned"
screen deck | head -n 2 | grep -q "A: continuity" && fail "C did not unpin reference A" deck
keys deck C-c
wait_for deck "EXITED=130"
echo "passed: at 200x60 PgDn, PgUp and Home drive the continuity lesson; C pins reference A (label at the top, letter on the curve) beside the live curve and unpins it"
