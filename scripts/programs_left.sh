#!/usr/bin/env bash
# Usage: scripts/programs_left.sh FOLDER — after a test run: fails (exit 1) when a program built in
# FOLDER still runs 15 s after the run ended, naming and killing it. A test that leaves a program
# behind is a defect, and CI would pay for it: the sanitizer build's apcs, its terminal hung up while
# it exited, was found spinning in LeakSanitizer's stop of its threads for good, three a run, each
# eating half a core of the rest of CI (and of every run after it on the same machine).
set -uo pipefail
source "$(dirname "$0")/../tests/e2e/ended_lib.sh"
folder=$(realpath "$1")
all_ended processes_from "$folder" "programs built in $folder still run 15 s after the tests ended"
