#!/usr/bin/env bash
# --keys from a pipe: the script given as a file, through bash's process substitution (a FIFO,
# /dev/fd/N) and as "-" (standard input) replays to the same files; "-" on a terminal is refused.
# Usage: keys_from_pipe.sh APCS EXAMPLE_FOLDER
set -uo pipefail
apcs=$1
example=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

for run in file pipe stdin; do
  mkdir "$work/$run" && cp "$example"/*.dat "$work/$run/" || fail "cannot copy $example"
done
script="$example/session.keys"
timeout 60 "$apcs" --workdir "$work/file" --keys "$script" < /dev/null > /dev/null 2> "$work/err.file"
status=$?; [ "$status" -eq 0 ] || fail "--keys FILE: exit $status: $(cat "$work/err.file")"
timeout 60 "$apcs" --workdir "$work/pipe" --keys <(cat "$script") < /dev/null > /dev/null 2> "$work/err.pipe"
status=$?; [ "$status" -eq 0 ] || fail "--keys <(...): exit $status: $(cat "$work/err.pipe")"
cat "$script" | timeout 60 "$apcs" --workdir "$work/stdin" --keys - > /dev/null 2> "$work/err.stdin"
status=$?; [ "$status" -eq 0 ] || fail "--keys -: exit $status: $(cat "$work/err.stdin")"

ls "$work/file"/inb*.dat > /dev/null 2>&1 || fail "the script wrote no in-betweens: $(ls "$work/file")"
for run in pipe stdin; do
  diff -r -x apcs.log "$work/file" "$work/$run" > "$work/diff" || fail "--keys $run differs from the file: $(cat "$work/diff")"
done
# "-" when standard input is the terminal: the session needs it for keys, so that is a usage error.
# util-linux's `script` gives it a terminal; scripts/install-deps.sh installs it (bsdutils), so
# without it the case fails rather than pass untried.
command -v script > /dev/null || fail "no 'script' (util-linux, Debian's bsdutils) to give apcs a terminal"
script -qec "$apcs --workdir $work/stdin --keys -" /dev/null < /dev/null > "$work/out.tty" 2>&1; status=$?
[ "$status" -eq 2 ] || fail "--keys - on a terminal: exit $status: $(cat "$work/out.tty")"
grep -qF -- "--keys -: standard input is a terminal" "$work/out.tty" || fail "no message: $(cat "$work/out.tty")"
echo "keys_from_pipe: file, pipe and standard input replay alike"
