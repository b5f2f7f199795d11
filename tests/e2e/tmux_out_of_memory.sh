#!/usr/bin/env bash
# End-to-end: an allocation that fails mid-session (the budget raised past what `ulimit -v` allows)
# ends the session with "apcs: out of memory" and exit 1, the terminal given back: echo and icanon
# on. Usage: tmux_out_of_memory.sh APCS
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

# Address space for the program and curses, far below what the path below asks for.
limit_kib=$((192 * 1024))
# AddressSanitizer reserves terabytes of address space at start: under ulimit -v it cannot run.
if ! (ulimit -v "$limit_kib" && "$apcs" --version) >/dev/null 2>&1; then
  echo "apcs does not start under ulimit -v $limit_kib (a sanitizer build?): skipped"
  exit 77
fi

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder oom

# Two-point keys, and a path of 10^6 control points (the most a file holds) from KEY1's first point to KEY2's: the
# points, their copies and their KB segments take over 250 MB (curve samples are computed, not held).
printf '0 0 0\n1 0 0\n' >"$work/key1.dat"
printf '0 0 10\n1 0 10\n' >"$work/key2.dat"
awk 'BEGIN { n = 1000000; for (i = 0; i < n; ++i) printf "%d %d %.6f\n", i % 2, (i % 3 == 1), i * 10 / (n - 1) }' >"$work/big.dat"
# The ends exactly: KEY1's first point, KEY2's first point.
sed -i '1s/.*/0 0 0/;$s/.*/0 0 10/' "$work/big.dat"

tmux -L "$socket" new-session -d -s oom -x 80 -y 25 -c "$work" \
  "ulimit -v $limit_kib; APCS_MEMORY_LIMIT=1T '$apcs' 2>err.txt; echo EXITED=\$?; $report_terminal_modes; sleep 60"
wait_for oom "Please keyin the KEY1 filename!"
tmux -L "$socket" send-keys -t oom Enter
wait_for oom "Please keyin the KEY2 filename!"
tmux -L "$socket" send-keys -t oom Enter
wait_for oom "THETA ,PHI & delay-time value."
tmux -L "$socket" send-keys -t oom Enter
wait_for oom "Please keyin the anix.dat filename"
tmux -L "$socket" send-keys -t oom 'big.dat' Enter
# Memory runs out reading the path, or past the slopes when the path is evaluated.
for _ in $(seq 1 300); do
  screen oom | grep -qF "EXITED=" && break
  if screen oom | grep -qF "Please input the slope : DS[0] ,DD[N]"; then
    tmux -L "$socket" send-keys -t oom Enter
    break
  fi
  sleep 0.1
done
wait_for oom "EXITED="
wait_for oom "MODES"
screen oom | grep -qF "EXITED=1" || { echo "expected exit status 1"; screen oom; exit 1; }
modes=$(screen oom | grep "MODES$")
case "$modes" in
  *-echo* | *-icanon*) echo "terminal not restored after running out of memory: $modes"; exit 1 ;;
  *echo*icanon* | *icanon*echo*) ;;
  *) echo "echo or icanon missing after running out of memory: $modes"; exit 1 ;;
esac
grep -qx "apcs: out of memory" "$work/err.txt" || { echo "no 'apcs: out of memory' on stderr:"; cat "$work/err.txt"; exit 1; }
echo "out of memory mid-session: exit 1, terminal restored"
