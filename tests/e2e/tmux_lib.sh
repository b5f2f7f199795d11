# Helpers for the tmux end-to-end tests; source it, then call tmux_test_folder NAME.

# A fresh work folder ($work) and a tmux server of the test's own ($socket, after NAME), both
# removed when the test ends.
# The programs under a test's tmux server end by its hang-up when the test ends. An ASan build's
# leak check, caught by that hang-up, was seen spinning for good after CI runs (its tracer waiting
# on a thread that never stopped), two of them a core each: leaks are the unit tests' business.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
source "$(dirname "${BASH_SOURCE[0]}")/ended_lib.sh"

tmux_test_folder() {
  work=$(mktemp -d)
  socket="apcs-$1-$$"
  trap 'tmux -L "$socket" kill-server 2>/dev/null || true; all_ended_in "$work"; rm -rf "$work"' EXIT
}

# A shell command for after the program in a pane: prints the terminal's echo and icanon modes
# ("echo icanon MODES" once the terminal is given back; "-echo -icanon MODES" if left raw).
report_terminal_modes='stty -a | tr " ;" "\n\n" | grep -E "^-?(echo|icanon)$" | tr "\n" " "; echo MODES'

# Fails unless the pane of session $1, its program run as "PROGRAM; echo EXITED=$?;
# $report_terminal_modes", reports exit 130 and a terminal with echo and icanon back (after $2).
expect_restored() {
  wait_for "$1" "EXITED=130"
  wait_for "$1" "MODES"
  modes=$(screen "$1" | grep "MODES$")
  case "$modes" in
    *-echo* | *-icanon*) echo "terminal not restored after $2: $modes"; exit 1 ;;
    *echo* ) [[ "$modes" == *icanon* ]] || { echo "no icanon after $2: $modes"; exit 1; } ;;
    *) echo "no echo after $2: $modes"; exit 1 ;;
  esac
}

# The text on the screen of tmux session $1.
screen() { tmux -L "$socket" capture-pane -p -t "$1"; }

# Waits up to 15 s until session $1 shows the text $2; otherwise prints the screen and fails.
wait_for() {
  for _ in $(seq 1 150); do
    screen "$1" | grep -qF -- "$2" && return 0
    sleep 0.1
  done
  echo "timed out waiting for: $2"; echo "--- screen:"; screen "$1"; exit 1
}

# A session NAME at 80x24 running COMMAND in $work, then reporting its exit status.
start_80x24() { tmux -L "$socket" new-session -d -s "$1" -x 80 -y 24 -c "$work" "$2; echo EXITED=\$?; sleep 60"; }
# Keys (tmux key names) to session $1, then a moment for the screen to follow.
keys_to() { local name=$1; shift; tmux -L "$socket" send-keys -t "$name" "$@"; sleep 0.2; }
# Fails with a message, and the screen of session $2 when named.
fail_showing() { echo "FAILED: $1"; [ $# -lt 2 ] || { echo "--- screen:"; screen "$2"; }; exit 1; }
