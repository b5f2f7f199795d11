#!/usr/bin/env bash
# Usage: scripts/programs_left.sh FOLDER — after a test run: fails (exit 1) when a program built in
# FOLDER still runs 15 s after the run ended, naming and killing it. A test that leaves a program
# behind is a defect, and CI would pay for it: the sanitizer build's apcs, its terminal hung up while
# it exited, was found spinning in LeakSanitizer's stop of its threads for good, three a run, each
# eating half a core of the rest of CI (and of every run after it on the same machine).
set -uo pipefail
folder=$(realpath "$1")
# find complains of processes that end while it looks: only what it printed counts.
running_from_folder() {
  { find /proc -mindepth 2 -maxdepth 2 -name exe -lname "$folder/*" -printf '%h\n' 2> /dev/null || true; } |
    sed 's|^/proc/||'
}
for _ in $(seq 150); do
  left=$(running_from_folder)
  [ -z "$left" ] && exit 0
  sleep 0.1
done
echo "FAILED: programs built in $folder still run 15 s after the tests ended:"
for pid in $left; do
  echo "  $pid: $(tr '\0' ' ' < "/proc/$pid/cmdline" 2> /dev/null)"
done
kill -KILL $left 2> /dev/null
exit 1
