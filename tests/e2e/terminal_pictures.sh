#!/usr/bin/env bash
# --sixel FILE and --kitty FILE write the picture --png writes (SPEC §7.2.1): for a path, a fit's
# and an inbetween's overlay, apcs draw and a scene, the sixel file decoded by ImageMagick and the
# kitty file's payload decoded (kitty_pixels.py) are the PNG's 720x522 pixels, byte for byte; "-"
# writes them to standard output; a FIFO, a folder, or the input (through a symbolic or a hard link) is
# refused as --png refuses it, with the same message. Usage: terminal_pictures.sh APCS DATA_FOLDER
# (skips, exit 77, without ImageMagick's convert or python3).
set -uo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
here=$(cd "$(dirname "$0")" && pwd)
for tool in convert python3; do
  command -v "$tool" > /dev/null || { echo "skipped: no $tool (scripts/install-deps.sh installs it)"; exit 77; }
done
convert -list format | grep -q '^ *SIXEL' || { echo "skipped: this ImageMagick reads no sixel"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
cp "$data"/n-to-l/*.dat "$work"/
cd "$work" || fail "cannot enter $work"

grey() { convert "$1" -colorspace gray -depth 8 "gray:$2" || fail "convert $1"; }
same_pixels() { # NAME: NAME.six and NAME.kitty show NAME.png's pixels
  [ "$(convert "$1.png" -format %wx%h info:)" = 720x522 ] || fail "$1.png is not 720x522"
  grey "$1.png" "$1.png.grey"
  grey "sixel:$1.six" "$1.six.grey"
  cmp -s "$1.png.grey" "$1.six.grey" || fail "$1.six decoded by ImageMagick differs from $1.png: $(cmp "$1.png.grey" "$1.six.grey")"
  python3 "$here/kitty_pixels.py" "$1.kitty" "$1.kitty.grey" 2> "$1.kitty.log" || fail "$1.kitty: $(cat "$1.kitty.log")"
  cmp -s "$1.png.grey" "$1.kitty.grey" || fail "$1.kitty's payload differs from $1.png: $(cmp "$1.png.grey" "$1.kitty.grey")"
  lit=$(tr -d '\000' < "$1.png.grey" | wc -c)
  [ "$lit" -gt 1000 ] || fail "$1.png has only $lit lit pixels"
  echo "$1: PNG $(wc -c < "$1.png") B, sixel $(wc -c < "$1.six") B, kitty $(wc -c < "$1.kitty") B ($(cat "$1.kitty.log")): the same $lit lit pixels"
}
pictures() { echo "--png $1.png --sixel $1.six --kitty $1.kitty"; }

# shellcheck disable=SC2046 # the picture options split into words on purpose
{
  "$apcs" path way1.dat --tension 0.5 $(pictures path) || fail "apcs path"
  "$apcs" fit key1.dat key2.dat way1.dat way4.dat --inbetweens 5 $(pictures fit) > /dev/null || fail "apcs fit"
  "$apcs" inbetween key1.dat key2.dat --inbetweens 4 $(pictures inbetween) > /dev/null || fail "apcs inbetween"
  "$apcs" draw key1.dat way1.dat way4.dat key2.dat $(pictures draw) || fail "apcs draw"
  "$apcs" play "$data"/robot/robot.scn $(pictures scene) > /dev/null || fail "apcs play"
}
for picture in path fit inbetween draw scene; do
  same_pixels "$picture"
done

# To standard output: the file's bytes.
"$apcs" path way1.dat --tension 0.5 --sixel - > stdout.six || fail "--sixel -"
cmp -s stdout.six path.six || fail "--sixel - wrote other bytes than --sixel FILE"
"$apcs" draw key1.dat way1.dat way4.dat key2.dat --kitty - > stdout.kitty || fail "--kitty -"
cmp -s stdout.kitty draw.kitty || fail "--kitty - wrote other bytes than --kitty FILE"

# Refused as --png refuses: the same status and message, the target left as it was.
mkfifo fifo.png fifo.six fifo.kitty
mkdir dir.png dir.six dir.kitty
ln -s way1.dat link.png; ln -s way1.dat link.six; ln -s way1.dat link.kitty
ln way1.dat hard.png; ln way1.dat hard.six; ln way1.dat hard.kitty
for target in fifo dir link hard; do
  timeout 20 "$apcs" path way1.dat --png "$target.png" > /dev/null 2> png.err; png_status=$?
  [ "$png_status" -ne 0 ] || fail "--png $target.png was written"
  for option in sixel:six kitty:kitty; do
    timeout 20 "$apcs" path way1.dat "--${option%%:*}" "$target.${option##*:}" > /dev/null 2> other.err; status=$?
    [ "$status" -eq "$png_status" ] || fail "--${option%%:*} $target: exit $status, --png's was $png_status"
    sed "s/$target\.${option##*:}/$target.png/g; s/--${option%%:*}/--png/g" other.err > other.as-png.err
    cmp -s png.err other.as-png.err || fail "--${option%%:*} $target says '$(cat other.err)', --png '$(cat png.err)'"
  done
  echo "$target: refused by all three, exit $png_status: $(head -1 png.err)"
done
cmp -s key1.dat "$data/n-to-l/key1.dat" && cmp -s way1.dat "$data/n-to-l/way1.dat" || fail "an input changed"
echo "passed: sixel and kitty files show the PNG's pixels, and are refused where the PNG is"
