#!/usr/bin/env bash
# End-to-end: SIGINT while the session takes the terminal over (after curses' cbreak, before the
# first screen: raise_in_cbreak.so raises it there) is a stop like any other: the program ends
# with exit 130 and gives the terminal back, echo and icanon on. Before, the batch commands'
# handler ended it at once and left the terminal raw.
# Usage: tmux_signal_at_takeover.sh APCS RAISE_IN_CBREAK_LIBRARY
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
library=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder takeover

tmux -L "$socket" new-session -d -s takeover -x 80 -y 25 -c "$work" \
  "LD_PRELOAD='$library' '$apcs' 2>err.txt; echo EXITED=\$?; $report_terminal_modes; sleep 60"
expect_restored takeover "SIGINT inside cbreak()"
grep -q "stopped" "$work/err.txt" || { cat "$work/err.txt"; echo "FAILED: no 'stopped' on stderr"; exit 1; }
echo "passed: exit 130, $modes, $(head -1 "$work/err.txt")"
