#!/usr/bin/env bash
# A handout prints from a real browser (issue 42 item 6): the N-to-L lesson's --handout --paper
# index.html, printed by Debian's chromium (--headless --print-to-pdf), gives a PDF with every page's
# picture, one or two to a sheet, black on white, with chromium's header and footer and without
# them. chromium and poppler-utils (pdfimages, pdfinfo, pdftoppm, pdftotext) are installed here
# when missing, as tests/e2e/debian_package.sh's set-up installs debhelper; where apt-get cannot
# install them (not root, no network) the test is skipped (exit 77).
# Usage: handout_print.sh APCS N_TO_L_FOLDER
set -uo pipefail
apcs=$1
data=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

# COMMAND from PACKAGE, installed with apt-get when it is missing and this is root.
need() {
  command -v "$1" > /dev/null && return 0
  if [ "$(id -u)" -eq 0 ] && command -v apt-get > /dev/null; then
    export DEBIAN_FRONTEND=noninteractive
    { apt-get install -y -qq --no-install-recommends "$2" ||
      { apt-get update -qq && apt-get install -y -qq --no-install-recommends "$2"; }; } < /dev/null > "$work/apt.log" 2>&1
  fi
  command -v "$1" > /dev/null ||
    { echo "skipped: no $1, and apt-get could not install $2 ($(tail -1 "$work/apt.log" 2>/dev/null || echo 'not root'))"; exit 77; }
}
need chromium chromium
need pdfimages poppler-utils
need pdfinfo poppler-utils
need pdftoppm poppler-utils
need pdftotext poppler-utils

cp "$data"/*.dat "$data"/lesson.keys "$work"/
"$apcs" --keys "$work/lesson.keys" --workdir "$work" --glyphs ascii --handout "$work/handout" --paper \
  < /dev/null > /dev/null 2> "$work/err" || fail "apcs --handout: exit $?: $(cat "$work/err")"
pages=$(find "$work/handout" -name '*.png' | wc -l)
[ "$pages" -ge 3 ] || fail "the handout has $pages pages: $(ls "$work/handout")"
[ "$(grep -c '<img ' "$work/handout/index.html")" -eq "$pages" ] || fail "index.html does not show the $pages pictures"

# Printed as chromium prints it by default (its header and footer in the page margins: the date,
# the title, the address, page numbers) and without them (--no-pdf-header-footer, as the manual
# says): every picture at its size (720 pixels wide), one or two on each sheet, in order, either way.
# Its own profile and home: a build daemon's HOME may not be writable; root needs --no-sandbox.
print_handout() { # PDF [CHROMIUM_FLAG]
  HOME=$work timeout 180 chromium --headless --no-sandbox --disable-gpu ${2:+"$2"} \
    --user-data-dir="$work/profile" --print-to-pdf="$1" "file://$work/handout/index.html" \
    > "$work/chromium.log" 2>&1 || fail "chromium --print-to-pdf ${2:-}: exit $?: $(tail -5 "$work/chromium.log")"
  [ -s "$1" ] || fail "chromium wrote no PDF: $(tail -5 "$work/chromium.log")"
  pdfimages -list "$1" > "$work/images" 2>&1 || fail "pdfimages: $(cat "$work/images")"
  images=$(awk 'NR > 2 && $3 == "image"' "$work/images" | wc -l)
  echo "${2:-with the header and footer}: the handout's $pages pages printed as $images pictures"
  [ "$images" -eq "$pages" ] || fail "the PDF holds $images pictures, the handout $pages: $(cat "$work/images")"
  awk 'NR > 2 && $3 == "image" && $4 != 720 { bad = 1 } END { exit bad }' "$work/images" ||
    fail "a picture is not 720 pixels wide: $(cat "$work/images")"
  sheets=$(pdfinfo "$1" | awk '/^Pages:/ { print $2 }')
  echo "on $sheets sheets"
  [ "$sheets" -eq $(((pages + 1) / 2)) ] || fail "$pages pictures on $sheets sheets, not two a sheet (${2:-})"
  per_sheet=$(awk 'NR > 2 && $3 == "image" { count[$1]++ } END { for (s in count) print count[s] }' "$work/images" | sort -u | tr '\n' ' ')
  [ "$per_sheet" = "2 " ] || [ "$per_sheet" = "1 2 " ] || fail "pictures a sheet: $per_sheet (${2:-})"
}
print_handout "$work/with-header.pdf"
pdftotext -f 1 -l 1 "$work/with-header.pdf" - | grep -q 'file://' ||
  fail "chromium printed no footer with the page's address: the default print is not what the manual describes"
print_handout "$work/handout.pdf" --no-pdf-header-footer
! pdftotext -f 1 -l 1 "$work/handout.pdf" - | grep -q 'file://' || fail "--no-pdf-header-footer left the footer"

# Ink on paper: the first sheet is mostly white (its pictures black on white, as --paper drew them).
pdftoppm -f 1 -l 1 -r 40 -gray "$work/handout.pdf" "$work/sheet" || fail "pdftoppm"
python3 - "$work"/sheet-*1.pgm <<'PYTHON' || fail "the first sheet is not mostly white"
import sys
data = open(sys.argv[1], "rb").read()
# A binary PGM: the header's four fields, then one byte a pixel.
fields = data.split(maxsplit=4)
pixels = fields[4]
white = sum(1 for value in pixels if value > 200) / len(pixels)
print(f"the first sheet is {white:.0%} white")
sys.exit(0 if white > 0.8 else 1)
PYTHON
echo "passed: chromium printed index.html: $images pictures of $pages pages on $sheets sheets"
