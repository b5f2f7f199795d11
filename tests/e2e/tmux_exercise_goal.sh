#!/usr/bin/env bash
# An exercise as a student meets it (issue 43 item 3): at 80x24 in a real terminal (tmux), paced a
# step per Space. At the goal the task stays on the caption row and the message line above the
# staff gives the goal's feedback (GOAL: ...); on the wrong staff line it names the line; the right
# keys bring GOAL REACHED, which the next key takes away; the student's keys are recorded as
# tokens between the GOAL line and the closing caption, and the recording rechecks headless.
# Usage: tmux_exercise_goal.sh APCS EXERCISES_FOLDER
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
exercises=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder goal
cp "$exercises"/key1.dat "$exercises"/key2.dat "$exercises"/way1.dat "$exercises"/exercise-2-continuity.keys "$work"/
fresh=$work/fresh
mkdir "$fresh"
cp "$exercises"/key1.dat "$exercises"/key2.dat "$exercises"/way1.dat "$fresh"/

keys() { keys_to "$@"; }
fail() { fail_showing "$@"; }
row() { screen student | sed -n "$1p"; }
task="Exercise 2: a corner at the middle point: CONTINUITY from -0.60 to -0.40"

start_80x24 student "$apcs --keys exercise-2-continuity.keys --pace step --glyphs ascii --record $work/mine.keys"
wait_for student "caption 0 of 3"
keys student Space
wait_for student "way1.dat, face-on"
# 8 came with the first caption; ENTER, then the task (the goal waits once it shows).
for _ in 1 2; do keys student Space; done
wait_for student "GOAL: continuity +0.00, want -0.60 to -0.40"
# The task on the caption row (the last), the feedback on the message line (row 19, above the staff).
row 24 | grep -qF " $task" || fail "the task is not on the caption row at the goal" student
row 19 | grep -qF " GOAL: continuity +0.00, want -0.60 to -0.40" || fail "the feedback is not on the message line" student

# On BIAS the feedback names the line the student is on and the goal's.
keys student Enter
wait_for student "GOAL: you are on BIAS; the goal is CONTINUITY: finish the staff, then Y"
row 24 | grep -qF " $task" || fail "the task left the caption row" student
keys student Enter Enter
wait_for student "Adjust the path again ? (Y/N)"
keys student Y
keys student 8
wait_for student "GOAL: you are on TENSION; the goal is CONTINUITY: Enter or Esc goes down a line"
keys student Enter
wait_for student "GOAL: continuity +0.00"
keys student J J
keys student 4 4
wait_for student "GOAL REACHED: continuity -0.40 (want -0.60 to -0.40)"
row 24 | grep -qF " Negative continuity turns DS and DD apart: the curve gets a corner" ||
  fail "the closing caption is not shown once the goal is reached" student
# Enter leaves CONTINUITY at -0.40 (6 would move it to -0.35, and the goal counts as the path
# stands when the session ends: SPEC 3.2).
keys student Enter
sleep 0.3
screen student | grep -qF "GOAL REACHED" && fail "GOAL REACHED stays after the next key" student
keys student q
keys student Y
wait_for student "EXITED=0"
# Back at the shell the student reads what was written and which file to hand in.
screen student | grep -qx "APCS is done. Files written:" || fail "no heading over the files written" student
screen student | grep -qx "Keystrokes recorded in $work/mine.keys" || fail "the recording's name is not said" student

grep -q "^goal reached: continuity -0.40 at key " "$work/apcs.log" || { cat "$work/apcs.log"; fail "apcs.log has no goal line"; }
# The recording: the student's keys as tokens after the GOAL line, the closing caption after them.
sed -n '/^GOAL /,/^;; Negative/p' "$work/mine.keys" | tr '\n' ' ' |
  grep -qF "GOAL VALUE CONTINUITY -0.6 -0.4 ENTER ENTER ENTER Y 8 ENTER J J 4 4 ;; Negative" ||
  { cat "$work/mine.keys"; fail "the recording does not keep the student's keys between the GOAL line and the caption"; }
"$apcs" --keys "$work/mine.keys" --workdir "$fresh" < /dev/null > /dev/null || fail "the recording does not recheck"
echo "ok: task on the caption row, GOAL feedback on the message line, wrong-line hints, GOAL REACHED, recording named at the end and rechecks"
