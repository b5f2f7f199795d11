#!/usr/bin/env bash
# End-to-end: the split of large keys (issue 16 item 7, issue 18 item 2) shows its progress, and
# Esc or Ctrl-C stop it at once: the count of files at the stop is far below the total, every file
# written is whole and no hidden temporary file is left.
# Usage: tmux_split.sh APCS
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder split

fail() { echo "FAILED: $1"; [ $# -lt 2 ] || { echo "--- screen:"; screen "$2"; }; exit 1; }

total=200000
# Two keys of $total points each: seconds of writing however fast the disk.
make_keys() {
  mkdir "$1"
  for which in 1 2; do
    awk -v n=$total -v k=$which 'BEGIN { print "PART cloud OPEN"; for (i = 0; i < n; i++) print i, i % 977 + k, k }' \
      > "$1/key$which.dat"
  done
}

# Starts APCS in folder $2 as session $1 and answers both key prompts with their defaults.
start_split() {
  tmux -L "$socket" new-session -d -s "$1" -x 80 -y 24 -c "$2" "ESCDELAY=25 '$apcs'; echo EXITED=\$?; sleep 60"
  wait_for "$1" "Please keyin the KEY1 filename!"
  tmux -L "$socket" send-keys -t "$1" Enter
  wait_for "$1" "Please keyin the KEY2 filename!"
  tmux -L "$socket" send-keys -t "$1" Enter
  wait_for "$1" "Splitting: ani"
}

path_files() { find "$1" -maxdepth 1 -name 'ani*.dat' | wc -l; }

# Every path file written holds its two points; nothing hidden is left.
check_files() {
  local folder=$1 what=$2
  leftovers=$(find "$folder" -maxdepth 1 -name '.*' -type f)
  [[ -z "$leftovers" ]] || fail "temporary files left after $what: $(echo "$leftovers" | head -3)"
  short=$(find "$folder" -maxdepth 1 -name 'ani*.dat' -exec wc -l {} + | awk '$2 != "total" && $1 != 2' | head -3)
  [[ -z "$short" ]] || fail "path files not whole after $what: $short"
}

passed=0

# --- Esc: back to the KEY2 prompt, the count said and the files written kept.
make_keys "$work/esc"
start_split esc "$work/esc"
tmux -L "$socket" send-keys -t esc Escape
wait_for esc "Split stopped: ani1.dat"
screen esc | grep -qF "Please keyin the KEY2 filename!" || fail "no KEY2 prompt after Esc" esc
stopped_at=$(tmux -L "$socket" capture-pane -p -J -t esc | sed -n 's/.*(\([0-9]*\) of '$total').*/\1/p' | tail -1)
[[ -n "$stopped_at" ]] || fail "no count in the stop message" esc
(( stopped_at < total / 2 )) || fail "Esc acted only after $stopped_at of $total files" esc
sleep 0.5
written=$(path_files "$work/esc")
[[ "$written" -eq "$stopped_at" ]] || fail "$written path files on disk, the message said $stopped_at" esc
screen esc | grep -qF "Splitting:" && fail "the progress line stayed after Esc" esc
check_files "$work/esc" Esc
passed=$((passed + 1))

# --- Ctrl-C: APCS ends (exit 130) with every file written whole.
make_keys "$work/ctrlc"
start_split ctrlc "$work/ctrlc"
tmux -L "$socket" send-keys -t ctrlc C-c
wait_for ctrlc "EXITED=130"
screen ctrlc | grep -qF "stopped; every file written so far is whole" || fail "no stop message after Ctrl-C" ctrlc
written=$(path_files "$work/ctrlc")
(( written > 0 && written < total / 2 )) || fail "Ctrl-C acted only after $written of $total files" ctrlc
check_files "$work/ctrlc" Ctrl-C
passed=$((passed + 1))

echo "split: $passed checks passed (Esc at $stopped_at, Ctrl-C at $written of $total files)"
