#!/usr/bin/env bash
# End-to-end: signals leave the terminal sane; a small terminal is told its size; a resize redraws.
# Usage: tmux_terminal_faults.sh APCS
set -euo pipefail
apcs=$1
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

work=$(mktemp -d)
socket="apcs-faults-$$"
cleanup() { tmux -L "$socket" kill-server 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT

source "$(dirname "$0")/tmux_lib.sh"
report_modes='stty -a | tr " ;" "\n\n" | grep -E "^-?(echo|icanon)$" | tr "\n" " "; echo MODES'

passed=0
for signal in INT TERM HUP; do
  name="sig$signal"
  tmux -L "$socket" new-session -d -s "$name" -x 80 -y 25 -c "$work" \
    "'$apcs'; echo EXITED=\$?; $report_modes; sleep 60"
  wait_for "$name" "Please keyin the KEY1 filename!"
  pkill -"$signal" -f "^$apcs\$" || pkill -"$signal" -x apcs
  wait_for "$name" "EXITED=130"
  wait_for "$name" "MODES"
  modes=$(screen "$name" | grep "MODES$")
  case "$modes" in
    *-echo* | *-icanon*) echo "terminal not restored after SIG$signal: $modes"; exit 1 ;;
    *echo* ) [[ "$modes" == *icanon* ]] || { echo "no icanon after SIG$signal: $modes"; exit 1; } ;;
    *) echo "no echo after SIG$signal: $modes"; exit 1 ;;
  esac
  passed=$((passed + 1))
done

tmux -L "$socket" new-session -d -s small -x 70 -y 20 -c "$work" "'$apcs'; echo EXITED=\$?; sleep 60"
wait_for small "The terminal must be at least 80x24 (it is 70x20)"
tmux -L "$socket" resize-window -t small -x 80 -y 23
wait_for small "The terminal must be at least 80x24 (it is 80x23)"
tmux -L "$socket" resize-window -t small -x 80 -y 24
wait_for small "Please keyin the KEY1 filename!"
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
