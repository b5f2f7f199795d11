#!/usr/bin/env bash
# Batch faults, one case a run (each its own CTest test): SIGPIPE ends quietly, TERM unset is a
# clear exit 3, a FIFO is neither read nor replaced (streams); output lost on a full standard
# output is exit 1 (full-output); a full disk leaves no partial file and keeps the old one
# (full-disk); a signal while the in-betweens are written is exit 130 (SPEC §1) and leaves no
# temporary file (signal); one while apcs grade replays leaves no private folder and whole rows
# (grade-signal); grading on a full disk is an error row, exit 1 (grade-full-disk); a private
# folder whose name is swapped for a link while grade runs is graded on, the link's target
# untouched (grade-swapped-folder).
# A case that cannot run here exits 77, which CTest reports as a skip (SKIP_RETURN_CODE); only
# the full-disk cases may, and only where the user is not root: as root (CI) a tmpfs it cannot
# mount is a failure.
# Usage: batch_faults.sh APCS streams|full-output|full-disk|signal|grade-signal|grade-full-disk|grade-swapped-folder
set -uo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
case_name=$2
work=$(mktemp -d)
cleanup() { umount "$work/small" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
fail() { echo "FAILED: $*"; exit 1; }
skip() { echo "skipped: $*"; exit 77; }
printf '0 0 0\n0 5 5\n9 9 9\n' > "$work/path.dat"

streams() {
  # SIGPIPE: the reader stops early; apcs must not print anything on stderr.
  "$apcs" path "$work/path.dat" --samples 5000 2> "$work/err" | head -n 1 > /dev/null
  status=${PIPESTATUS[0]}
  [ ! -s "$work/err" ] || fail "SIGPIPE printed: $(cat "$work/err")"
  # Its own write into the closed pipe: the quiet 141 (128 + SIGPIPE) of GNU tools, not a stop.
  [ "$status" -eq 141 ] || fail "apcs path --print | head: exit $status, not 141"

  # TERM unset, with a terminal-less stdin: the session needs --keys (exit 3), and says so.
  env -u TERM "$apcs" < /dev/null > /dev/null 2> "$work/err"; status=$?
  [ "$status" -eq 3 ] || fail "exit $status without a terminal"
  grep -q "give --keys FILE" "$work/err" || fail "no message: $(cat "$work/err")"

  # A FIFO as the input file: refused at once (exit 1), never waited on.
  mkfifo "$work/fifo.dat" || fail "cannot make a FIFO"
  timeout 10 "$apcs" path "$work/fifo.dat" > /dev/null 2> "$work/err"; status=$?
  [ "$status" -ne 124 ] || fail "apcs path hung on a FIFO"
  [ "$status" -eq 1 ] || fail "exit $status on a FIFO input"
  grep -qF "fifo.dat: is not a regular file (a FIFO); expected a file" "$work/err" || fail "no message: $(cat "$work/err")"
  for command in "inbetween $work/fifo.dat $work/path.dat" "fit $work/path.dat $work/path.dat $work/fifo.dat $work/path.dat"; do
    # shellcheck disable=SC2086
    timeout 10 "$apcs" $command --out "$work" > /dev/null 2> "$work/err"; status=$?
    [ "$status" -eq 1 ] || fail "exit $status for apcs $command"
    grep -qF "is not a regular file (a FIFO)" "$work/err" || fail "apcs $command: no message: $(cat "$work/err")"
  done

  # A FIFO, or a link to a device, as the PNG: refused (exit 1), left as it is, no .bak.
  mkfifo "$work/fifo.png"
  timeout 10 "$apcs" path "$work/path.dat" --png "$work/fifo.png" > /dev/null 2> "$work/err"; status=$?
  [ "$status" -eq 1 ] || fail "exit $status for --png FIFO"
  grep -qF "is not a regular file (a FIFO); APCS writes only regular files" "$work/err" || fail "no message: $(cat "$work/err")"
  [ -p "$work/fifo.png" ] && [ ! -e "$work/fifo.bak" ] || fail "the FIFO was replaced: $(ls -la "$work")"
  ln -s /dev/null "$work/null.png"
  "$apcs" path "$work/path.dat" --png "$work/null.png" > /dev/null 2> "$work/err"; status=$?
  [ "$status" -eq 1 ] || fail "exit $status for --png to a link to /dev/null"
  grep -qF "is a symbolic link to /dev/null, which is not a regular file" "$work/err" || fail "no message: $(cat "$work/err")"
  [ -L "$work/null.png" ] && [ -c /dev/null ] || fail "the link or /dev/null was replaced"
}

full_output() {
  # A full standard output: the output is lost, and that is said (exit 1), for --print and --help.
  [ -w /dev/full ] || fail "no /dev/full to write to"
  printf '0 0 0\n1 0 0\n' > "$work/k1.dat"; printf '0 1 0\n1 1 0\n' > "$work/k2.dat"
  printf '0 0 0\n0 1 0\n' > "$work/first.dat"; printf '1 0 0\n1 1 0\n' > "$work/last.dat"
  mkdir -p "$work/fitted"
  for command in "path $work/path.dat --print" "inbetween $work/path.dat $work/path.dat --print" \
                 "path $work/path.dat --print --samples 5000" \
                 "fit $work/k1.dat $work/k2.dat $work/first.dat $work/last.dat --out $work/fitted --print" "--help"; do
    # shellcheck disable=SC2086
    "$apcs" $command > /dev/full 2> "$work/err"; status=$?
    [ "$status" -eq 1 ] || fail "exit $status for apcs $command > /dev/full"
    grep -qxF "apcs: cannot write to standard output: No space left on device" "$work/err" \
      || fail "apcs $command > /dev/full: $(cat "$work/err")"
  done
}

full_disk() {
  # A full disk: a 64 KiB tmpfs. Mounting needs root: elsewhere a skip, as root a must.
  mkdir -p "$work/small"
  if ! mount -t tmpfs -o size=64k tmpfs "$work/small" 2> "$work/err"; then
    [ "$(id -u)" -eq 0 ] && fail "root cannot mount a tmpfs: $(cat "$work/err")"
    skip "not root, so no tmpfs to fill: $(cat "$work/err")"
  fi
  awk 'BEGIN { for (i = 0; i < 20000; i++) printf "0 %d %d\n", i, i % 7 }' > "$work/key1.dat"
  awk 'BEGIN { for (i = 0; i < 20000; i++) printf "5 %d %d\n", i, i % 5 }' > "$work/key2.dat"
  printf '0 0 0\n5 0 0\n' > "$work/first.dat"
  printf '0 19999 0\n5 19999 4\n' > "$work/last.dat"
  echo "old" > "$work/small/inb001.dat"
  "$apcs" fit "$work/key1.dat" "$work/key2.dat" "$work/first.dat" "$work/last.dat" --out "$work/small" \
    > /dev/null 2> "$work/err"; status=$?
  [ "$status" -eq 1 ] || fail "exit $status on a full disk"
  # Refused before the first file is written, in one line: what the files need, what is free
  # (issue 33); a disk that fills anyway says "No space left on device".
  grep -Eq "the in-between files need about .* \(12 files\); the folder has .* free|No space left on device" \
    "$work/err" || fail "no reason given: $(cat "$work/err")"
  [ "$(cat "$work/small/inb001.dat")" = "old" ] || fail "the old inb001.dat was not kept"
  leftovers=$(find "$work/small" -name '.*' -type f | wc -l)
  [ "$leftovers" -eq 0 ] || fail "temporary files left: $(ls -a "$work/small")"
}

# Sends SIGNAL to PID (a child of this shell) as soon as `find FIND_ARGUMENTS...` prints a name;
# prints PID's exit status, or "missed" when it ended before.
signal_when_found() {
  local pid=$1 signal=$2
  shift 2
  while kill -0 "$pid" 2>/dev/null; do
    if [ -n "$(find "$@" 2>/dev/null | head -1)" ]; then
      kill -s "$signal" "$pid"
      wait "$pid"; echo $?
      return
    fi
    sleep 0.002
  done
  wait "$pid"
  echo missed
}

# Starts `apcs fit` on keys of POINTS points into $work/signal/out and sends SIGNAL as soon as a
# hidden temporary in-between file shows; prints the exit status, or "missed" when the fit ended
# before one was seen.
signal_while_writing() {
  local signal=$1 points=$2
  rm -rf "$work/signal" && mkdir -p "$work/signal/out"
  awk -v n="$points" 'BEGIN { for (i = 0; i < n; i++) printf "0 %d %d\n", i, i % 7 }' > "$work/signal/key1.dat"
  awk -v n="$points" 'BEGIN { for (i = 0; i < n; i++) printf "5 %d %d\n", i, i % 5 }' > "$work/signal/key2.dat"
  printf '0 0 0\n5 0 0\n' > "$work/signal/first.dat"
  printf '0 %d 0\n5 %d 4\n' "$((points - 1))" "$((points - 1))" > "$work/signal/last.dat"
  "$apcs" fit "$work/signal/key1.dat" "$work/signal/key2.dat" "$work/signal/first.dat" "$work/signal/last.dat" \
    --inbetweens 40 --out "$work/signal/out" > /dev/null 2>&1 &
  signal_when_found $! "$signal" "$work/signal/out" -name '.inb*' -type f
}

stopping_signals() {
  # Each stopping signal of SPEC §1 while the in-betweens are written, and SIGPIPE sent by another
  # process (kill -PIPE: a stop, not a closed pipe): exit 130 and no hidden temporary file left
  # behind. A fit too quick to be caught is tried again on more points.
  for name in TERM INT HUP QUIT USR1 USR2 PIPE; do
    status=missed
    for points in 300000 600000 1200000; do
      status=$(signal_while_writing "$name" "$points")
      [ "$status" = missed ] || break
    done
    [ "$status" != missed ] || fail "SIG$name: the fit was never caught writing its in-betweens"
    [ "$status" -eq 130 ] || fail "SIG$name while writing: exit $status, SPEC §1 says 130"
    leftovers=$(find "$work/signal/out" -name '.*' -type f | wc -l)
    [ "$leftovers" -eq 0 ] || fail "SIG$name left $leftovers temporary files: $(ls -a "$work/signal/out" | head)"
  done
}

# `apcs grade` of 400 recordings with TMPDIR=$work/grade/tmp, its CSV in $work/grade/out.csv,
# SIGNAL sent once the CSV holds 2 KB (a dozen rows graded, a replay under way); prints the exit
# status, or "missed" when it ended first.
signal_while_grading() {
  local signal=$1 exercises
  exercises=$(dirname "$0")/../../data/exercises
  rm -rf "$work/grade" && mkdir -p "$work/grade/tmp" "$work/grade/ex" "$work/grade/in"
  cp "$exercises"/*.keys "$exercises"/*.dat "$work/grade/ex/"
  for i in $(seq 400); do cp "$exercises/answers/exercise-1-tension-answer.keys" "$work/grade/in/$i.keys"; done
  TMPDIR=$work/grade/tmp "$apcs" grade "$work/grade/ex/exercise-1-tension.keys" "$work/grade/in"/*.keys \
    > "$work/grade/out.csv" 2>/dev/null &
  signal_when_found $! "$signal" "$work/grade/out.csv" -size +2k
}

grading_signals() {
  # A signal that stops apcs grade mid-replay: exit 130, and its private folder under TMPDIR (the
  # exercise's copies, the work folder of the replay) is gone with everything in it.
  for name in TERM INT HUP; do
    status=$(signal_while_grading "$name")
    [ "$status" != missed ] || fail "SIG$name: apcs grade was never caught replaying"
    [ "$status" -eq 130 ] || fail "SIG$name while grading: exit $status, SPEC §1 says 130"
    left=$(find "$work/grade/tmp" -mindepth 1 | head -5)
    [ -z "$left" ] || fail "SIG$name left in TMPDIR: $left"
    # Every row it had graded, each whole: the CSV ends with a line end, each line of 7 fields.
    [ "$(tail -c 1 "$work/grade/out.csv" | od -An -c | tr -d ' ')" = '\n' ] ||
      fail "SIG$name cut the CSV inside a row: $(tail -c 80 "$work/grade/out.csv")"
    cut=$(awk -F, 'NF != 7' "$work/grade/out.csv" | head -1)
    [ -z "$cut" ] || fail "SIG$name left a row that is not whole: $cut"
    rows=$(($(wc -l < "$work/grade/out.csv") - 1))
    [ "$rows" -ge 10 ] || fail "SIG$name: only $rows rows of those graded were printed"
  done
}

grading_in_a_swapped_folder() {
  # A TMPDIR others may write: while grade runs, its private folder's name is moved away and a
  # link to another folder put in its place. Grade reaches its folder through its descriptor: it
  # grades on, and nothing in the link's target is made or removed (by name, work/ there went).
  local exercises private
  exercises=$(dirname "$0")/../../data/exercises
  mkdir -p "$work/shared" "$work/ex" "$work/in"
  # The work folders of the replays are work-0 … work-59: the target holds one of each name.
  for i in $(seq 0 59); do mkdir -p "$work/victim/work-$i" && echo precious > "$work/victim/work-$i/keep"; done
  cp "$exercises"/*.keys "$exercises"/*.dat "$work/ex/"
  for i in $(seq 60); do cp "$exercises/answers/exercise-1-tension-answer.keys" "$work/in/$i.keys"; done
  TMPDIR=$work/shared "$apcs" grade "$work/ex/exercise-1-tension.keys" "$work/in"/*.keys \
    > "$work/out.csv" 2> "$work/err" &
  local pid=$!
  for _ in $(seq 2000); do
    private=$(find "$work/shared" -mindepth 2 -maxdepth 2 -name 'work-*' -printf '%h\n' 2>/dev/null | head -1)
    [ -n "$private" ] && break
    sleep 0.005
  done
  [ -n "$private" ] || { wait "$pid"; fail "apcs grade was never caught replaying"; }
  mv "$private" "$work/shared/moved"
  ln -s "$work/victim" "$private"
  wait "$pid"; status=$?
  [ "$(cat "$work"/victim/work-*/keep 2>/dev/null | grep -c precious)" -eq 60 ] ||
    fail "the link's target lost a work-N/keep: $(ls -la "$work/victim" 2>&1)"
  [ "$(find "$work/victim" -mindepth 1 | wc -l)" -eq 120 ] || fail "made in the link's target: $(find "$work/victim")"
  [ "$status" -eq 0 ] || fail "exit $status: $(cat "$work/err")"
  # Seen twice on a loaded machine (a row 'no' with no value, 2026-11-29): grade's stderr and the
  # log of a work folder left say why, next time.
  [ "$(grep -c ',yes,+0.50,L L L 6,$' "$work/out.csv")" -eq 60 ] ||
    fail "not every row yes: $(cat "$work/out.csv") stderr: $(cat "$work/err") left: $(find "$work/shared" "$work/victim" 2>&1 | head -40)"
  [ -L "$private" ] || fail "the link put in the folder's place was removed"
}

grading_on_a_full_disk() {
  # TMPDIR on a 36 KiB tmpfs: the replay's session cannot write its files, so its keys go to other
  # prompts than the student's did. The row is an error naming what could not be written, exit 1;
  # never a verdict (it was 'no', exit 0, nothing said).
  local exercises
  exercises=$(dirname "$0")/../../data/exercises
  mkdir -p "$work/small" "$work/ex"
  if ! mount -t tmpfs -o size=36k tmpfs "$work/small" 2> "$work/err"; then
    [ "$(id -u)" -eq 0 ] && fail "root cannot mount a tmpfs: $(cat "$work/err")"
    skip "not root, so no tmpfs to fill: $(cat "$work/err")"
  fi
  cp "$exercises"/*.keys "$exercises"/*.dat "$work/ex/"
  TMPDIR=$work/small "$apcs" grade "$work/ex/exercise-1-tension.keys" \
    "$exercises/answers/exercise-1-tension-answer.keys" > "$work/out.csv" 2> "$work/err"; status=$?
  [ "$status" -eq 1 ] || fail "exit $status grading on a full disk: $(cat "$work/out.csv" "$work/err")"
  grep -q ",GOAL VALUE TENSION 0.4 0.6,error,,,$" "$work/out.csv" || fail "no error row: $(cat "$work/out.csv")"
  grep -q "No space left on device" "$work/err" || fail "the reason is not named: $(cat "$work/err")"
  [ -z "$(find "$work/small" -mindepth 1 | head -1)" ] || fail "left in TMPDIR: $(find "$work/small" | head)"
}

case $case_name in
  streams) streams ;;
  full-output) full_output ;;
  full-disk) full_disk ;;
  signal) stopping_signals ;;
  grade-signal) grading_signals ;;
  grade-full-disk) grading_on_a_full_disk ;;
  grade-swapped-folder) grading_in_a_swapped_folder ;;
  *) fail "no case '$case_name' (streams, full-output, full-disk, signal, grade-signal, grade-full-disk, grade-swapped-folder)" ;;
esac
echo "batch_faults $case_name: passed"
