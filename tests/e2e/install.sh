#!/usr/bin/env bash
# `cmake --install` into a DESTDIR, then the installed apcs run from another folder: figures reads
# the installed examples (a damaged installed copy is what it complains about, and APCS_DATA
# overrides it), a headless example session writes the in-betweens, the man page and the bash
# completion are in place. Usage: install.sh CMAKE BUILD_FOLDER SOURCE_FOLDER
set -uo pipefail
cmake=$1
build=$2
source_tree=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
unset APCS_DATA

DESTDIR="$work/root" "$cmake" --install "$build" --prefix /usr/local > "$work/install.log" 2>&1 ||
  fail "cmake --install: $(cat "$work/install.log")"
prefix="$work/root/usr/local"
apcs="$prefix/bin/apcs"
for file in bin/apcs share/apcs/n-to-l/session.keys share/apcs/stick/key1.dat share/apcs/snake-apple/apple.dat \
            share/doc/apcs/manual.txt share/doc/apcs/README.md share/man/man1/apcs.1 \
            share/bash-completion/completions/apcs; do
  [ -f "$prefix/$file" ] || fail "$file is not installed: $(find "$work/root" -type f | head -20)"
done
[ -x "$apcs" ] || fail "bin/apcs is not executable"
if command -v groff > /dev/null; then
  warnings=$(groff -man -Tutf8 -ww -z "$prefix/share/man/man1/apcs.1" 2>&1)
  [ -z "$warnings" ] || fail "the man page has warnings: $warnings"
fi

mkdir "$work/elsewhere" "$work/figures"
cd "$work/elsewhere" || fail "cannot enter $work/elsewhere"
"$apcs" figures --out "$work/figures" > "$work/out" 2> "$work/err" || fail "figures: $(cat "$work/err")"
[ "$(wc -l < "$work/out")" -eq 12 ] || fail "figures wrote: $(cat "$work/out")"
[ -s "$work/figures/example-3-snake-apple.png" ] || fail "no example-3-snake-apple.png"
[ -s "$work/figures/fig-3-2-1.png" ] || fail "no fig-3-2-1.png"
[ -s "$work/figures/fig-3-3-3.png" ] || fail "no fig-3-3-3.png (the robot from the installed data/robot)"

# The installed examples, not the source tree's, are the ones read: without one of them figures fails
# and names the installed file; APCS_DATA then points it elsewhere.
rm "$prefix/share/apcs/stick/key2.dat"
"$apcs" figures --out "$work/figures" > /dev/null 2> "$work/err"; status=$?
[ "$status" -eq 1 ] || fail "exit $status with an installed example missing"
grep -qF "$prefix/share/apcs/stick/key2.dat" "$work/err" || fail "not the installed file: $(cat "$work/err")"
APCS_DATA="$source_tree/data" "$apcs" figures --out "$work/figures" > /dev/null 2> "$work/err" ||
  fail "APCS_DATA=$source_tree/data: $(cat "$work/err")"
APCS_DATA="$work/none" "$apcs" figures --out "$work/figures" > /dev/null 2> "$work/err"; status=$?
[ "$status" -eq 1 ] || fail "exit $status with APCS_DATA naming no folder"
grep -qF "APCS_DATA: $work/none is not a folder" "$work/err" || fail "no message: $(cat "$work/err")"

# The shipped example session, replayed without a terminal in a copy of the installed example.
cp -r "$prefix/share/apcs/n-to-l" "$work/session"
"$apcs" --keys "$prefix/share/apcs/n-to-l/session.keys" --workdir "$work/session" < /dev/null > "$work/out" 2> "$work/err" ||
  fail "the session: exit $?: $(cat "$work/err")"
[ -s "$work/session/inb001.dat" ] || fail "no inb001.dat: $(ls "$work/session")"
# The exercises install without their answers, which go with the documentation; an installed answer
# replays from there on a copy of the installed exercises.
[ ! -e "$prefix/share/apcs/exercises/answers" ] || fail "the answers are installed beside the exercises"
[ -f "$prefix/share/doc/apcs/answers/exercise-1-tension-answer.keys" ] ||
  fail "no answers in share/doc/apcs/answers: $(ls "$prefix/share/doc/apcs")"
cp -r "$prefix/share/apcs/exercises" "$work/ex"
"$apcs" --keys "$prefix/share/doc/apcs/answers/exercise-1-tension-answer.keys" --workdir "$work/ex" < /dev/null \
  > "$work/out" 2> "$work/err" || fail "the installed answer: exit $?: $(cat "$work/err")"
echo "passed: installed, figures from share/apcs, APCS_DATA, a headless session, the answers apart"
