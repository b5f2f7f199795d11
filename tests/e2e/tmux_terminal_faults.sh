#!/usr/bin/env bash
# End-to-end: signals leave the terminal sane; a small terminal is told its size; a resize redraws.
# Usage: tmux_terminal_faults.sh APCS [DATA_FOLDER]
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=${2:-$(dirname "$0")/../../data/n-to-l}
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder faults



passed=0
# PIPE: sent by another process to the interactive session, a stop like the others (issue 45).
for signal in INT TERM HUP QUIT USR1 USR2 ALRM PIPE; do
  name="sig$signal"
  tmux -L "$socket" new-session -d -s "$name" -x 80 -y 25 -c "$work" \
    "'$apcs'; echo EXITED=\$?; $report_terminal_modes; sleep 60"
  wait_for "$name" "Please keyin the KEY1 filename!"
  pkill -"$signal" -f "^$apcs\$" || pkill -"$signal" -x apcs
  expect_restored "$name" "SIG$signal"
  passed=$((passed + 1))
done

# Ctrl-\ typed at the keyboard (SIGQUIT from the terminal's driver) once the split has written its
# files: handled like Ctrl-C, no core, and every file written is whole (no temporary left behind).
quit_work="$work/quit"
mkdir "$quit_work"
cp "$data"/key1.dat "$data"/key2.dat "$quit_work"/
tmux -L "$socket" new-session -d -s ctrlquit -x 80 -y 25 -c "$quit_work" \
  "ulimit -c 0; '$apcs'; echo EXITED=\$?; $report_terminal_modes; sleep 60"
wait_for ctrlquit "Please keyin the KEY1 filename!"
tmux -L "$socket" send-keys -t ctrlquit Enter
wait_for ctrlquit "Please keyin the KEY2 filename!"
tmux -L "$socket" send-keys -t ctrlquit Enter
wait_for ctrlquit "THETA ,PHI & delay-time value."
tmux -L "$socket" send-keys -t ctrlquit 'C-\'
expect_restored ctrlquit "Ctrl-\\"
screen ctrlquit | grep -qF "stopped; every file written so far is whole" \
  || { echo "no stop message after Ctrl-\\"; screen ctrlquit; exit 1; }
leftovers=$(find "$quit_work" -name '.*' -type f)
[[ -z "$leftovers" ]] || { echo "temporary files left after Ctrl-\\: $leftovers"; exit 1; }
[[ -s "$quit_work/ani1.dat" ]] || { echo "the split wrote no ani1.dat before Ctrl-\\"; ls -la "$quit_work"; exit 1; }
cmp -s "$data/key1.dat" "$quit_work/key1.dat" || { echo "key1.dat changed after Ctrl-\\"; exit 1; }
passed=$((passed + 1))

# Ctrl-Z in a shell: APCS suspends with the terminal given back (the shell's job line, echo and
# icanon on), and fg brings it back redrawn, still at its prompt.
tmux -L "$socket" new-session -d -s suspend -x 80 -y 25 -c "$work" "bash --norc --noprofile"
tmux -L "$socket" send-keys -t suspend "PS1='$ '; '$apcs'" Enter
wait_for suspend "Please keyin the KEY1 filename!"
tmux -L "$socket" send-keys -t suspend C-z
wait_for suspend "Stopped"
tmux -L "$socket" send-keys -t suspend "$report_terminal_modes" Enter
wait_for suspend "MODES"
modes=$(screen suspend | grep "MODES$" | tail -1)
[[ " $modes " == *" echo "* && " $modes " == *" icanon "* ]] \
  || { echo "terminal not given back at Ctrl-Z: $modes"; screen suspend; exit 1; }
tmux -L "$socket" send-keys -t suspend clear Enter
tmux -L "$socket" send-keys -t suspend fg Enter
wait_for suspend "Please keyin the KEY1 filename!"
tmux -L "$socket" send-keys -t suspend C-c
tmux -L "$socket" send-keys -t suspend 'echo EXITED=$?' Enter
wait_for suspend "EXITED=130"
passed=$((passed + 1))

tmux -L "$socket" new-session -d -s small -x 70 -y 20 -c "$work" "'$apcs'; echo EXITED=\$?; sleep 60"
wait_for small "The terminal must be at least 80x23 (it is 70x20)"
wait_for small "Keys are ignored until it is larger; Ctrl-C quits"
# Typed before the resize, so read before it: the 79x23 screen shows they were seen and dropped.
tmux -L "$socket" send-keys -t small abc
tmux -L "$socket" resize-window -t small -x 79 -y 23
wait_for small "The terminal must be at least 80x23 (it is 79x23)"
tmux -L "$socket" resize-window -t small -x 80 -y 22
wait_for small "The terminal must be at least 80x23 (it is 80x22)"
# 80x23, an 80x24 window under tmux's status line, is enough.
tmux -L "$socket" resize-window -t small -x 80 -y 23
wait_for small "Please keyin the KEY1 filename!"
! screen small | grep -q abc || { echo "keys typed at the too-small screen reached the KEY1 prompt"; screen small; exit 1; }
passed=$((passed + 1))

tmux -L "$socket" new-session -d -s noterm -x 80 -y 25 -c "$work" "TERM=no-such-terminal '$apcs'; echo EXITED=\$?; sleep 60"
wait_for noterm "is unknown (no terminfo entry)"
wait_for noterm "EXITED=3"
passed=$((passed + 1))
tmux -L "$socket" new-session -d -s unset -x 80 -y 25 -c "$work" "env -u TERM '$apcs'; echo EXITED=\$?; sleep 60"
wait_for unset "TERM is not set"
wait_for unset "EXITED=3"
passed=$((passed + 1))
echo "$passed passed, 0 failed"
