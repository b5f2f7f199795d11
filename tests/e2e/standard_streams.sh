#!/usr/bin/env bash
# "-" reads a .dat file from standard input and writes a picture to standard output; each stream
# holds one file. Usage: standard_streams.sh APCS DATA_FOLDER (data/n-to-l)
set -uo pipefail
apcs=$1
data=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

# A path from standard input prints what the file prints.
"$apcs" path "$data/way1.dat" --print > "$work/from_file" || fail "path from the file"
"$apcs" path - --print < "$data/way1.dat" > "$work/from_stdin" || fail "path from standard input"
cmp -s "$work/from_file" "$work/from_stdin" || fail "standard input read otherwise than the file"

# A key frame from a pipe, and its error named as standard input.
"$apcs" inbetween "$data/key1.dat" "$data/key2.dat" --print > "$work/frames_file" || fail "inbetween from files"
cat "$data/key1.dat" | "$apcs" inbetween - "$data/key2.dat" --print > "$work/frames_pipe" || fail "inbetween from a pipe"
cmp -s "$work/frames_file" "$work/frames_pipe" || fail "a piped key frame differs"
printf '0 0\n1 x\n' | "$apcs" path - 2> "$work/err"; status=$?
[ "$status" -eq 1 ] || fail "exit $status for a bad file on standard input"
grep -qxF "standard input:2: expected a number, found 'x'" "$work/err" || fail "message: $(cat "$work/err")"

# An endless stream is refused at its first NUL, not read to the size limit.
timeout 20 "$apcs" path - < /dev/zero 2> "$work/err"; status=$?
[ "$status" -eq 1 ] || fail "exit $status for /dev/zero on standard input"
grep -qxF "standard input:1: NUL byte; expected a text file" "$work/err" || fail "message: $(cat "$work/err")"

# Pictures to standard output: the same bytes as the file, and nothing else on the stream.
"$apcs" path "$data/way1.dat" --png "$work/file.png" || fail "path --png FILE"
"$apcs" path "$data/way1.dat" --png - > "$work/stdout.png" || fail "path --png -"
cmp -s "$work/file.png" "$work/stdout.png" || fail "--png - wrote other bytes than --png FILE"
(cd "$work" && "$apcs" fit "$data/key1.dat" "$data/key2.dat" "$data/way1.dat" "$data/way4.dat" --png-raw - > raw.png) ||
  fail "fit --png-raw -"
[ "$(head -c 8 "$work/raw.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "fit --png-raw - is no PNG"
[ ! -e "$work/inb001.dat" ] || fail "fit with a picture wrote in-between files into the current folder"

# One stream, one file: usage errors, exit 2.
for arguments in "fit - - $data/way1.dat $data/way4.dat" "path $data/way1.dat --png - --print" \
                 "path $data/way1.dat --png - --png-raw -" "--png -"; do
  # shellcheck disable=SC2086
  "$apcs" $arguments < /dev/null > "$work/out" 2> "$work/err"; status=$?
  [ "$status" -eq 2 ] || fail "exit $status for: $arguments"
  [ ! -s "$work/out" ] || fail "output for: $arguments"
done
echo "standard streams: all checks passed"
