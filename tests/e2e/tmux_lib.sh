# Helpers for the tmux end-to-end tests; source it after setting $socket (the tmux server).

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
