# Sourced by the e2e libraries and scripts/programs_left.sh: a test passes only when every program it
# started has ended (issue 45: an AddressSanitizer-built apcs, orphaned by its terminal's end, once
# spun a core for 34 minutes after its test had passed).

# The process ids whose working folder is $1 or inside it (one look at /proc).
processes_in() {
  # find complains of processes that end while it looks: only what it printed counts.
  { find /proc -mindepth 2 -maxdepth 2 -name cwd -printf '%h %l\n' 2> /dev/null || true; } |
    awk -v folder="$1" '$2 == folder || index($2, folder "/") == 1 { sub("/proc/", "", $1); print $1 }'
}

# The process ids running a program file inside folder $1 (one look at /proc).
processes_from() {
  { find /proc -mindepth 2 -maxdepth 2 -name exe -lname "$1/*" -printf '%h\n' 2> /dev/null || true; } |
    sed 's|^/proc/||'
}

# Waits up to 15 s until `LISTER FOLDER` lists no process; otherwise says WHAT, names them, kills them
# and fails (exit 1).
all_ended() {
  local lister=$1 folder=$2 what=$3 left
  # This shell's own children (the looks at /proc) must not be found in the folder.
  cd /
  for _ in $(seq 150); do
    left=$("$lister" "$folder")
    [ -z "$left" ] && return 0
    sleep 0.1
  done
  echo "FAILED: $what:"
  for pid in $left; do echo "  $pid: $(tr '\0' ' ' < "/proc/$pid/cmdline" 2> /dev/null)"; done
  kill -KILL $left 2> /dev/null
  exit 1
}

# Waits up to 15 s for the programs in folder $1 to end; kills what is left and fails (exit 1) then.
all_ended_in() { all_ended processes_in "$1" "still running 15 s after the test ended"; }
