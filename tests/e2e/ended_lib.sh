# Sourced by the e2e libraries: a test passes only when every program it started in its work folder
# has ended (issue 45: an AddressSanitizer-built apcs, orphaned by its terminal's end, once spun a
# core for 34 minutes after its test had passed).

# The process ids whose working folder is $1 or inside it (one look at /proc).
processes_in() {
  # find complains of processes that end while it looks: only what it printed counts.
  { find /proc -mindepth 2 -maxdepth 2 -name cwd -printf '%h %l\n' 2> /dev/null || true; } |
    awk -v folder="$1" '$2 == folder || index($2, folder "/") == 1 { sub("/proc/", "", $1); print $1 }'
}

# Waits up to 15 s for the programs in folder $1 to end; kills what is left and fails (exit 1) then.
all_ended_in() {
  local left
  # This shell's own children (the looks at /proc) must not be found in the folder.
  cd /
  for _ in $(seq 150); do
    left=$(processes_in "$1")
    [ -z "$left" ] && return 0
    sleep 0.1
  done
  echo "FAILED: still running 15 s after the test ended:"
  for pid in $left; do tr '\0' ' ' < "/proc/$pid/cmdline" 2> /dev/null; echo; done
  kill -KILL $left 2> /dev/null
  exit 1
}
