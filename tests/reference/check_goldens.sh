#!/usr/bin/env bash
# Holds the approved in-between files against fit_model.py, a model written apart from the C++
# code, so that a wrong approval fails: the N-to-L session's (tests/golden/n-to-l, from its own
# approved way1.dat and way4.dat) and every example's 12 (tests/golden/examples, from the path
# files the example's session writes when APCS replays it). The end slopes are the ones each
# session.keys types; the path files the session writes hold them too (SLOPES), so the two agree. Without python3 it exits 77, which
# CTest reports as a skip (scripts/install-deps.sh installs python3).
# Usage: check_goldens.sh APCS SOURCE_DIR
set -uo pipefail
apcs=$1
source_dir=$2
model="$source_dir/tests/reference/fit_model.py"
golden="$source_dir/tests/golden"
command -v python3 > /dev/null || { echo "skipped: no python3"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

# The in-between files K:FILE of a folder, for K = 1 ... 12.
all_twelve() { for k in $(seq 1 12); do printf '%d:%s/inb%03d.dat ' "$k" "$1" "$k"; done; }

echo "n-to-l session (tests/golden/n-to-l):"
python3 "$model" "$source_dir/data/n-to-l/key1.dat" "$source_dir/data/n-to-l/key2.dat" \
  "$golden/n-to-l/way1.dat" "$golden/n-to-l/way4.dat" --inbetweens 12 --first-slopes 1 1 --last-slopes 0.5 1 \
  "1:$golden/n-to-l/inb001.dat" "6:$golden/n-to-l/inb006.dat" "12:$golden/n-to-l/inb012.dat" \
  || fail "the N-to-L session's approved in-betweens are not what the model makes of its approved paths"

# example, first path, its slopes, last path, its slopes (as session.keys gives them)
while read -r example first first_slopes_0 first_slopes_1 last last_slopes_0 last_slopes_1; do
  echo "$example (tests/golden/examples/$example):"
  mkdir "$work/$example"
  cp "$source_dir/data/$example"/* "$work/$example/"
  "$apcs" --keys "$work/$example/session.keys" --workdir "$work/$example" < /dev/null > /dev/null 2> "$work/err"
  status=$?
  [ "$status" -eq 0 ] || fail "$example: the session's replay ended with exit $status: $(cat "$work/err")"
  # shellcheck disable=SC2046
  python3 "$model" "$work/$example/key1.dat" "$work/$example/key2.dat" "$work/$example/$first" "$work/$example/$last" \
    --inbetweens 12 --first-slopes "$first_slopes_0" "$first_slopes_1" --last-slopes "$last_slopes_0" "$last_slopes_1" \
    $(all_twelve "$golden/examples/$example") \
    || fail "$example: the approved in-betweens are not what the model makes of the session's paths"
done << 'END'
n-to-l way1.dat 1 1 way4.dat 0.5 1
stick way1.dat 0 0 way5.dat 1 1
snake-apple way1.dat 1 1 way7.dat 1 0.5
END
echo "check_goldens: every approved in-between file agrees with the model"
