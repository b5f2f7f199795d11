#!/usr/bin/env bash
# Batch faults: a full disk leaves no partial file and keeps the old one; SIGPIPE ends quietly;
# TERM unset is a clear exit 3; a FIFO is neither read nor replaced; output lost on a full
# standard output is exit 1. Usage: batch_faults.sh APCS
set -uo pipefail
apcs=$1
work=$(mktemp -d)
cleanup() { umount "$work/small" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
passed=0
fail() { echo "FAILED: $*"; exit 1; }

# SIGPIPE: the reader stops early; apcs must not print anything on stderr.
printf '0 0 0\n0 5 5\n9 9 9\n' > "$work/path.dat"
"$apcs" path "$work/path.dat" --samples 5000 2> "$work/err" | head -n 1 > /dev/null
[ ! -s "$work/err" ] || fail "SIGPIPE printed: $(cat "$work/err")"
passed=$((passed + 1))

# TERM unset, with a terminal-less stdin: the session needs --keys (exit 3), and says so.
env -u TERM "$apcs" < /dev/null > /dev/null 2> "$work/err"; status=$?
[ "$status" -eq 3 ] || fail "exit $status without a terminal"
grep -q "give --keys FILE" "$work/err" || fail "no message: $(cat "$work/err")"
passed=$((passed + 1))

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
passed=$((passed + 1))

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
passed=$((passed + 1))

# A full standard output: the output is lost, and that is said (exit 1), for --print and --help.
if [ -w /dev/full ]; then
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
  passed=$((passed + 1))
else
  echo "skipped the full-output case: no /dev/full"
fi

# A full disk: a 64 KiB tmpfs (needs root; skipped elsewhere).
mkdir -p "$work/small"
if mount -t tmpfs -o size=64k tmpfs "$work/small" 2>/dev/null; then
  awk 'BEGIN { for (i = 0; i < 20000; i++) printf "0 %d %d\n", i, i % 7 }' > "$work/key1.dat"
  awk 'BEGIN { for (i = 0; i < 20000; i++) printf "5 %d %d\n", i, i % 5 }' > "$work/key2.dat"
  printf '0 0 0\n5 0 0\n' > "$work/first.dat"
  printf '0 19999 0\n5 19999 4\n' > "$work/last.dat"
  echo "old" > "$work/small/inb001.dat"
  "$apcs" fit "$work/key1.dat" "$work/key2.dat" "$work/first.dat" "$work/last.dat" --out "$work/small" \
    > /dev/null 2> "$work/err"; status=$?
  [ "$status" -eq 1 ] || fail "exit $status on a full disk"
  grep -q "No space left on device" "$work/err" || fail "no reason given: $(cat "$work/err")"
  [ "$(cat "$work/small/inb001.dat")" = "old" ] || fail "the old inb001.dat was not kept"
  leftovers=$(find "$work/small" -name '.*' -type f | wc -l)
  [ "$leftovers" -eq 0 ] || fail "temporary files left: $(ls -a "$work/small")"
  passed=$((passed + 1))
else
  echo "skipped the full-disk case: cannot mount a tmpfs here"
fi
# SIGTERM while the in-betweens are being written: no hidden temporary file is left behind.
mkdir -p "$work/signal"
awk 'BEGIN { for (i = 0; i < 300000; i++) printf "0 %d %d\n", i, i % 7 }' > "$work/signal/key1.dat"
awk 'BEGIN { for (i = 0; i < 300000; i++) printf "5 %d %d\n", i, i % 5 }' > "$work/signal/key2.dat"
printf '0 0 0\n5 0 0\n' > "$work/signal/first.dat"
printf '0 299999 0\n5 299999 4\n' > "$work/signal/last.dat"
mkdir -p "$work/signal/out"
"$apcs" fit "$work/signal/key1.dat" "$work/signal/key2.dat" "$work/signal/first.dat" "$work/signal/last.dat" \
  --inbetweens 40 --out "$work/signal/out" > /dev/null 2>&1 &
pid=$!
caught=0
for _ in $(seq 1 2000); do
  if [ -n "$(find "$work/signal/out" -name '.inb*' -type f 2>/dev/null | head -1)" ]; then
    kill -TERM "$pid" 2>/dev/null && caught=1
    break
  fi
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.005
done
wait "$pid"; status=$?
if [ "$caught" -eq 1 ] && [ "$status" -eq 143 ]; then
  leftovers=$(find "$work/signal/out" -name '.*' -type f | wc -l)
  [ "$leftovers" -eq 0 ] || fail "SIGTERM left $leftovers temporary files: $(ls -a "$work/signal/out" | head)"
  passed=$((passed + 1))
else
  echo "skipped the SIGTERM case: the writing was not caught in the act (exit $status)"
fi
echo "$passed passed, 0 failed"
