#!/usr/bin/env bash
# The deck's keys that fell between the replay's states (issue 55), as a teacher meets them in an
# 80x23 pane: , and . step the paused surface animation a frame a press; Esc then PgUp gives the
# keyboard back and returns to the caption's screen; PgUp at "End of the script" shows caption N
# of N; PgDn at exercise 1's goal says GOAL skipped.
# Usage: tmux_deck_rows_80x23.sh APCS DATA_FOLDER
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder deckrows
fail() { fail_showing "$@"; }
keys() { keys_to "$@"; }
start() {
  tmux -L "$socket" new-session -d -s "$1" -x 80 -y 23 -c "$2" "LANG=C.UTF-8 $apcs $3; echo EXITED=\$?; sleep 60"
  [ "$(tmux -L "$socket" display -p -t "$1" '#{pane_width}x#{pane_height}')" = 80x23 ] || fail "the pane is not 80x23"
}
# The rows under the badge's (the badge names the key just pressed).
below_badge() { screen "$1" | tail -n +2; }
# The number N of "In-between N of 12" on session $1's screen.
frame_shown() { screen "$1" | grep -o 'In-between [0-9]* of 12' | head -n 1 | cut -d' ' -f2; }

# --- , and . on the surface lesson's animation, paced at a frame a second.
mkdir "$work/surface"
cp "$data"/n-to-l/*.dat "$data"/n-to-l/lesson-surface.keys "$work/surface/"
start surface "$work/surface" "--keys lesson-surface.keys --pace step --delay 1000 --glyphs ascii"
captions=$(grep -c '^;;' "$work/surface/lesson-surface.keys")
wait_for surface "caption 0 of $captions"
# PgDn K shows caption K with its keys played: caption 5's key starts the frames.
for _ in $(seq 1 5); do keys surface PageDown; done
wait_for surface "In-between"
keys surface .
wait_for surface "(paused)"
first=$(frame_shown surface)
for _ in 1 2 3 4; do keys surface .; done
sleep 0.3
[ "$(frame_shown surface)" = $((first + 4)) ] || fail "five presses of . did not step five frames (from $first)" surface
screen surface | grep -qF "caption 5 of $captions" || fail "the caption moved while stepping frames" surface
keys surface ,
sleep 0.3
[ "$(frame_shown surface)" = $((first + 3)) ] || fail ", did not step a frame back" surface
keys surface Space
wait_for surface "Press any key to see all frames"
screen surface | grep -qF "caption 5 of $captions" || fail "Space after the pause played a step of the script" surface

# --- Esc, a key of the teacher's, PgUp: the caption's screen again.
mkdir "$work/lesson"
cp "$data"/n-to-l/*.dat "$data"/n-to-l/lesson.keys "$work/lesson/"
start lesson "$work/lesson" "--keys lesson.keys --pace step --glyphs ascii"
captions=$(grep -c '^;;' "$work/lesson/lesson.keys")
wait_for lesson "caption 0 of $captions"
keys lesson PageDown PageDown
wait_for lesson "caption 2 of $captions"
sleep 0.3
at_two=$(below_badge lesson)
keys lesson Escape
wait_for lesson "your keyboard: PgUp/PgDn/Home return"
keys lesson 8
keys lesson PageUp
wait_for lesson "key PGUP | caption 2 of $captions"
sleep 0.3
[ "$(below_badge lesson)" = "$at_two" ] || fail "PgUp after Esc did not return to caption 2's screen" lesson
keys lesson Escape
keys lesson Home
wait_for lesson "key HOME | caption 1 of $captions"

# --- PgUp at "End of the script": caption N of N.
for _ in $(seq 0 "$captions"); do keys lesson PageDown; done
wait_for lesson "End of the script"
keys lesson PageUp
wait_for lesson "caption $captions of $captions"

# --- PgDn at exercise 1's goal: GOAL skipped, the closing caption marked.
mkdir "$work/exercise"
cp "$data"/exercises/*.dat "$data"/exercises/exercise-1-tension.keys "$work/exercise/"
start exercise "$work/exercise" "--keys exercise-1-tension.keys --pace step --glyphs ascii"
wait_for exercise "caption 0 of"
keys exercise Space
wait_for exercise "caption 1 of"
keys exercise Space
wait_for exercise "GOAL: tension +0.00, want +0.40 to +0.60"
keys exercise PageDown
wait_for exercise "GOAL skipped: tension +0.00, want +0.40 to +0.60"
screen exercise | grep -qF "(skipped) Tension shortens both tangents" || fail "the closing caption is not marked skipped" exercise
grep -q "goal skipped" "$work/exercise/apcs.log" || fail "apcs.log has no goal skipped line"
echo "ok: , . step the paused animation; Esc PgUp and Home give the keyboard back; PgUp at the end: caption N of N; GOAL skipped"
