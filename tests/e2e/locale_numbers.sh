#!/usr/bin/env bash
# Numbers are written and read with '.' in every locale (SPEC section 1): under a German locale,
# whose decimal point is a comma, the headless session and the batch commands give the same bytes
# as under C.UTF-8 — standard output, standard error, exit status and every file written.
# The locale is made here with localedef from Debian's locales sources (LOCPATH), so the test needs
# no locale installed on the machine; without localedef or the sources it is a skip (exit 77).
# Usage: locale_numbers.sh APCS DATA_FOLDER (data)
set -uo pipefail
apcs=$1
data=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

command -v localedef > /dev/null || { echo "skipped: no localedef"; exit 77; }
mkdir "$work/locales"
localedef -i de_DE -f UTF-8 "$work/locales/de_DE.UTF-8" > "$work/localedef.log" 2>&1 ||
  [ -f "$work/locales/de_DE.UTF-8/LC_NUMERIC" ] || { echo "skipped: localedef de_DE: $(cat "$work/localedef.log")"; exit 77; }
export LOCPATH="$work/locales"
# The test is only a test if the locale really writes 0,5.
[ "$(LC_ALL=de_DE.UTF-8 printf '%.1f' 0,5 2>/dev/null)" = "0,5" ] ||
  fail "the generated de_DE.UTF-8 does not use a decimal comma (printf says $(LC_ALL=de_DE.UTF-8 printf '%.1f' 0,5 2>&1))"

# Runs APCS in a fresh copy of the examples under LOCALE and keeps what it printed and wrote.
run_in() {
  local locale=$1 name=$2
  shift 2
  local folder="$work/$locale/$name"
  mkdir -p "$folder"
  cp -r "$data/n-to-l/." "$folder/"
  (cd "$folder" && LC_ALL="$locale" "$apcs" "$@" < /dev/null > "$folder.out" 2> "$folder.err"; echo "exit $?" >> "$folder.out")
}

run_both() {
  run_in C.UTF-8 "$@"
  run_in de_DE.UTF-8 "$@"
}

run_both session --keys session.keys
run_both path path way1.dat --tension 0.5 --continuity -0.25 --bias 0.125 --accel 0.3 --print
run_both inbetween inbetween key1.dat key2.dat --print
run_both fit fit key1.dat key2.dat way1.dat way4.dat --accel 0.25 --inbetweens 5 --out fitted --print
run_both draw draw key1.dat --png key1.png --svg key1.svg
run_both play play "$data/robot/robot.scn" --print

diff -r "$work/C.UTF-8" "$work/de_DE.UTF-8" > "$work/diff" ||
  fail "de_DE.UTF-8 gave other bytes than C.UTF-8: $(head -20 "$work/diff")"
for run in session path inbetween fit draw play; do
  grep -qx "exit 0" "$work/C.UTF-8/$run.out" || fail "$run did not end with 0: $(cat "$work/C.UTF-8/$run.err")"
done
grep -q "0\.5" "$work/C.UTF-8/path.out" || fail "apcs path --print shows no tension 0.5: $(head -5 "$work/C.UTF-8/path.out")"
echo "passed: the session and path, inbetween, fit, draw and play give the same bytes in de_DE.UTF-8 as in C.UTF-8"
