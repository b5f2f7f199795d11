#!/usr/bin/env bash
# Batch faults: a full disk leaves no partial file and keeps the old one; SIGPIPE ends quietly;
# TERM unset is a clear exit 3. Usage: batch_faults.sh APCS
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
echo "$passed passed, 0 failed"
