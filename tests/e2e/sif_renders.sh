#!/usr/bin/env bash
# `apcs export --sif` documents rendered by Synfig's own renderer (`synfig`, at each document's own
# size), the moving circle found in every frame (sif_centres.py) and compared in the view plane:
#   tcb:       a 2-D path of five control points with tension, continuity and bias of ±0.5 (read
#              along `top`) and way1.dat (3-D, the session's view 30 40): every frame within 1e-3 of
#              the path's size of `apcs path --print`'s curve sample of that frame, at the waypoints
#              and between them;
#   frames:    a path with an acceleration, --sif-motion frames: every frame on APCS's own frame
#              (KEY1, each in-between, KEY2);
#   animation: the N-to-L example exported with fit's inputs renders every frame, each with its
#              outlines drawn; the stick and snake examples render their 14 frames.
# Usage: sif_renders.sh APCS DATA_FOLDER (skips, exit 77, without synfig or python3).
set -uo pipefail
apcs=$1
data=$2
here=$(cd "$(dirname "$0")" && pwd)
for tool in synfig python3; do
  command -v "$tool" > /dev/null || { echo "skipped: no $tool (scripts/install-deps.sh installs it)"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
cp "$data"/n-to-l/*.dat "$work"/
cd "$work" || fail "cannot enter $work"
cat > tcb.dat <<'PATH'
; x y z  tension continuity bias acceleration
0 0 0   0.5 0 0 0
2 3 0   -0.5 0.3 0.2 0
5 1 0   0 -0.5 0.5 0
7 4 0   0.3 0.5 -0.5 0
9 0 0   0 0 0 0
PATH
cat > accel.dat <<'PATH'
0 0 0   0 0 0 0.6
3 4 0   0.2 0 0 -0.4
8 2 0   0 0 0 0
PATH

render() { # SIF PREFIX: every frame of SIF as PREFIX.NNNN.ppm
  synfig "$1" -t ppm -o "$2.ppm" > "$2.log" 2>&1 || fail "synfig $1: $(tail -3 "$2.log")"
}

compare() { # NAME PATH_FILE THETA PHI MODE [export options…]
  local name=$1 path=$2 theta=$3 phi=$4 mode=$5
  shift 5
  "$apcs" export "$path" --sif "$name.sif" "$@" 2> "$name.err" || fail "apcs export $path: $(cat "$name.err")"
  "$apcs" path "$path" --print --samples 12 > "$name.print" || fail "apcs path $path"
  render "$name.sif" "$name"
  result=$(python3 "$here/sif_centres.py" "$name.sif" "$name" "$name.print" "$theta" "$phi" "$mode") ||
    fail "$name: $result"
  echo "$name: $result"
}

compare tcb tcb.dat -90 0 curve
compare way1 way1.dat 30 40 curve
compare frames accel.dat -90 0 frames --sif-motion frames --samples 12
grep -q "acceleration" frames.err && fail "--sif-motion frames keeps the acceleration, yet said: $(cat frames.err)"
"$apcs" export accel.dat --sif accel-tcb.sif 2> accel-tcb.err || fail "apcs export accel.dat"
grep -q "not carried to Synfig: the acceleration 0.6 of the span from control point 1 to 2" accel-tcb.err ||
  fail "a TCB export of an acceleration does not say it is left out: $(cat accel-tcb.err)"
grep -q "<!-- Not carried by Synfig" accel-tcb.sif || fail "the TCB document does not say what it left out"
# Saying so keeps it a document: Synfig renders it, and APCS reads it back as the path it was.
render accel-tcb.sif accel-tcb
"$apcs" path accel-tcb.sif --print > accel-back.print 2> accel-back.err || fail "apcs path accel-tcb.sif: $(cat accel-back.err)"
"$apcs" path accel.dat --print > accel.print || fail "apcs path accel.dat"
# The curve is the same (the accelerations, left out, move only the in-betweens).
curve() { sed -n '/^# curve/,/^# inbetweens/p' "$1"; }
[ "$(curve accel-back.print)" = "$(curve accel.print)" ] || fail "accel-tcb.sif read back is not accel.dat's curve"

"$apcs" export key1.dat key2.dat way1.dat way4.dat --sif n-to-l.sif || fail "apcs export of the N-to-L animation"
render n-to-l.sif n-to-l
frames=$(ls n-to-l.[0-9][0-9][0-9][0-9].ppm | wc -l)
[ "$frames" -eq 14 ] || fail "the N-to-L animation rendered $frames frames, not KEY1, 12 in-betweens and KEY2"
python3 - n-to-l.[0-9][0-9][0-9][0-9].ppm <<'PY' || fail "an N-to-L frame is blank"
import re, sys
for name in sys.argv[1:]:
    data = open(name, "rb").read()
    pixels = data[re.match(rb"P6\s+\d+\s+\d+\s+\d+\s", data).end():]
    if sum(1 for v in pixels[::3] if v < 128) < 100:
        sys.exit(f"{name}: the outlines are not drawn")
PY
# The other shipped examples: the stick falling (an open graphic) and the snake (its paths as the
# session wrote them).
"$apcs" export "$data"/stick/key1.dat "$data"/stick/key2.dat "$data"/stick/way1.dat "$data"/stick/way5.dat \
  --sif stick.sif || fail "apcs export of the stick"
render stick.sif stick
"$apcs" export "$data"/snake-apple/key1.dat "$data"/snake-apple/key2.dat "$data"/snake-apple/way1.dat \
  "$data"/snake-apple/way7.dat --sif snake.sif || fail "apcs export of the snake"
render snake.sif snake
for name in stick snake; do
  [ "$(ls $name.[0-9][0-9][0-9][0-9].ppm | wc -l)" -eq 14 ] || fail "$name: not 14 frames rendered"
done
echo "passed: Synfig renders the exported paths within 1e-3 of APCS's points in every frame, and the N-to-L animation's $frames frames, the stick's and the snake's"
