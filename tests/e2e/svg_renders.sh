#!/usr/bin/env bash
# The SVG pictures are drawn by common viewers as the PNG shows them: for a path, a fit's overlay of
# every frame and a scene's (KEY1 or frame 0 solid, the last dashed, the others dotted), the car's
# scene with its lettered waypoints, and apcs draw's overlay, the SVG rendered by librsvg's
# rsvg-convert and by ImageMagick's convert lights at least 95 % of the PNG's lit pixels within one
# pixel. Usage: svg_renders.sh APCS DATA_FOLDER (skips, exit 77, without rsvg-convert or convert).
set -uo pipefail
apcs=$1
data=$2
here=$(cd "$(dirname "$0")" && pwd)
for tool in rsvg-convert convert python3; do
  command -v "$tool" > /dev/null || { echo "skipped: no $tool (scripts/install-deps.sh installs it)"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
cp "$data"/n-to-l/*.dat "$work"/
cd "$work" || fail "cannot enter $work"

"$apcs" path way1.dat --png path.png --svg path.svg || fail "apcs path"
"$apcs" fit key1.dat key2.dat way1.dat way4.dat --inbetweens 5 --png fit.png --svg fit.svg > /dev/null || fail "apcs fit"
"$apcs" play "$data"/robot/robot.scn --png scene.png --svg scene.svg > /dev/null || fail "apcs play"
"$apcs" play "$data"/car/car.scn --png car.png --svg car.svg > /dev/null || fail "apcs play car"
"$apcs" draw key1.dat way1.dat way4.dat key2.dat --png draw.png --svg draw.svg || fail "apcs draw"
grep -l 'clip-path\|stroke-dasharray' ./*.svg && fail "an SVG leans on clip-path or stroke-dasharray"

# The first row of the message line in a PNG of the monitor's shape (text row 18: raster row 261,
# 1.5 rows each, less the boundary's two pixels above it).
text_top=390
plain_pgm() { convert "$1" -colorspace gray -depth 8 -compress none "pgm:$2" || fail "convert $1"; }
for picture in path fit scene car draw; do
  plain_pgm "$picture.png" "$picture.pgm"
  rsvg-convert "$picture.svg" -o "$picture-rsvg.png" || fail "rsvg-convert $picture.svg"
  convert "$picture.svg" "$picture-magick.png" || fail "convert $picture.svg"
  for renderer in rsvg magick; do
    plain_pgm "$picture-$renderer.png" "$picture-$renderer.pgm"
    # The lines (the drawing area, above the message line: rows 0 ... 389 of 522) are the SVG's own
    # pieces and must match; the text is a monospace font standing in for the 9x14 VGA font, which
    # lights other pixels of the same letters (about 85 %), so it is held to less.
    read -r lit covered share < <(python3 "$here/svg_coverage.py" "$picture.pgm" "$picture-$renderer.pgm" 0 "$text_top") ||
      fail "svg_coverage.py $picture"
    echo "$picture.svg by $renderer: $covered of the PNG's $lit lit line pixels within one pixel ($share)"
    [ "$lit" -gt 1000 ] || fail "$picture.png has only $lit lit pixels"
    python3 -c "import sys; sys.exit(0 if $share >= 0.95 else 1)" || fail "$picture.svg by $renderer covers $share < 0.95"
    read -r lit covered share < <(python3 "$here/svg_coverage.py" "$picture.pgm" "$picture-$renderer.pgm" "$text_top" 9999) ||
      fail "svg_coverage.py $picture, the text"
    echo "  its text: $covered of the PNG's $lit lit pixels within one pixel ($share)"
    python3 -c "import sys; sys.exit(0 if $share >= 0.8 else 1)" || fail "$picture.svg's text by $renderer covers $share < 0.8"
    # And the other way: what the rendering lights lies on the PNG's pixels, so that a rendering
    # that lights everything (a background, a line the clip should have cut) cannot pass.
    read -r drawn kept back_share < <(python3 "$here/svg_coverage.py" "$picture-$renderer.pgm" "$picture.pgm") ||
      fail "svg_coverage.py $picture, the other way"
    echo "  and $kept of its $drawn lit pixels lie within one pixel of the PNG's ($back_share)"
    python3 -c "import sys; sys.exit(0 if $back_share >= 0.9 else 1)" ||
      fail "$picture.svg by $renderer lights pixels the PNG does not: $back_share < 0.9"
  done
done
echo "passed: rsvg-convert and ImageMagick draw the path, the fit and scene overlays, the car's letters and the dashes as the PNGs"
