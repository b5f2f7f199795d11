#!/usr/bin/env bash
# Configuring: APCS_FONT (-D or the environment) chooses the PSF font, gzipped or not; a missing
# font stops the configure with a message naming console-setup-linux and APCS_FONT.
# Usage: font_choice.sh CMAKE SOURCE_FOLDER
set -uo pipefail
cmake=$1
source_tree=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
configure() { "$cmake" -S "$source_tree" -B "$work/build" -DAPCS_BUILD_TESTS=OFF "$@" > "$work/log" 2>&1; }

configure -DAPCS_FONT="$work/none.psf.gz"; status=$?
[ "$status" -ne 0 ] || fail "configured without a font"
grep -qF "APCS_FONT: $work/none.psf.gz is missing" "$work/log" || fail "no message: $(cat "$work/log")"
grep -qF "console-setup-linux" "$work/log" || fail "the package is not named: $(cat "$work/log")"

default_font=/usr/share/consolefonts/Lat15-VGA14.psf.gz
[ -f "$default_font" ] || { echo "console-setup-linux is not installed"; exit 77; }
gzip -dc "$default_font" > "$work/plain.psf"
rm -rf "$work/build"
APCS_FONT="$work/plain.psf" configure || fail "configure with APCS_FONT in the environment: $(cat "$work/log")"
grep -qxF "APCS_FONT:FILEPATH=$work/plain.psf" "$work/build/CMakeCache.txt" ||
  fail "the environment's font was not taken: $(grep APCS_FONT "$work/build/CMakeCache.txt")"
echo "passed: a missing font is said, APCS_FONT chooses another"
