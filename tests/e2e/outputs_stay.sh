#!/usr/bin/env bash
# Outputs stay where they are put (issue 56), one case a run (each its own CTest test):
#   links         an output that is a symbolic link leading out of its folder (--record, a chain of
#                 links, a handout's pages and index, --png, play --out) is refused before anything
#                 is written: the file it leads to stays as it was and gets no .bak beside it;
#   names         a file name with ESC ] ... BEL in it reaches stderr and grade's CSV escaped
#                 (\x1B ... \x07), for grade, path, draw, fit, play, --keys, --record, --workdir;
#   handout-folder a handout goes only into a new or empty folder or an earlier handout's: a folder
#                 of the user's (their index.html, index.bak) is refused and left as it was; an
#                 earlier, longer handout's extra pages are named, not deleted;
#   swapped-folder play --out whose folder is renamed mid-run and replaced by a link to another
#                 folder writes every frame into the folder it opened (now renamed), none into
#                 the other folder.
# The files a test makes stand in for the victim's. Usage: outputs_stay.sh APCS DATA CASE
set -uo pipefail
apcs=$1
data=$2
case_name=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
export LC_ALL=C.UTF-8

# A session's folder w/ with the N-to-L keys and script, and a folder victim/ beside it holding
# files a link could lead to.
setup() {
  mkdir -p "$work/w" "$work/victim"
  cp "$data"/n-to-l/*.dat "$data"/n-to-l/session.keys "$data"/n-to-l/lesson.keys "$work/w/"
  for name in passwd a b c pic frm; do echo "victim's $name" > "$work/victim/$name"; done
}

# The victim's files are as setup made them, and nothing was added beside them.
victim_untouched() {
  for name in passwd a b c pic frm; do
    [ "$(cat "$work/victim/$name")" = "victim's $name" ] || fail "$1: victim/$name was replaced"
  done
  [ "$(ls -A "$work/victim" | wc -l)" -eq 6 ] || fail "$1: files added beside the victim's: $(ls -A "$work/victim")"
}

# Runs apcs ARGS... (stdin /dev/null); fails unless it exits 1 and stderr holds TEXT.
refused_with() {
  local text=$1
  shift
  "$apcs" "$@" < /dev/null > "$work/out" 2> "$work/err"; local status=$?
  [ "$status" -eq 1 ] || fail "apcs $*: exit $status, not 1: $(cat "$work/err")"
  grep -qF -- "$text" "$work/err" || fail "apcs $*: expected '$text' on stderr: $(cat "$work/err")"
}

links() {
  setup
  local leads="which leads out of its folder"
  ln -s ../victim/passwd "$work/w/my.keys"
  refused_with "w/my.keys: is a symbolic link to ../victim/passwd, $leads" \
    --workdir "$work/w" --keys "$work/w/session.keys" --record "$work/w/my.keys" --glyphs ascii
  victim_untouched "--record through a link"
  ln -s hop.keys "$work/w/chain.keys"; ln -s ../victim/passwd "$work/w/hop.keys"
  refused_with "w/chain.keys: is a symbolic link to hop.keys, $leads" \
    --workdir "$work/w" --keys "$work/w/session.keys" --record "$work/w/chain.keys" --glyphs ascii
  victim_untouched "--record through a chain of links"

  # A handout folder whose index and first pages are links: refused before the first page.
  mkdir "$work/h"
  ln -s ../victim/a "$work/h/index.html"
  ln -s ../victim/b "$work/h/01-w-i-a-control-point-halfway.png"
  ln -s ../victim/c "$work/h/01-w-i-a-control-point-halfway.txt"
  refused_with "$leads" --workdir "$work/w" --keys "$work/w/lesson.keys" --handout "$work/h" --glyphs ascii
  victim_untouched "--handout through links"
  [ "$(ls -A "$work/h" | wc -l)" -eq 3 ] || fail "the handout wrote pages: $(ls -A "$work/h")"

  ln -s ../victim/pic "$work/w/pic.png"
  refused_with "w/pic.png: is a symbolic link to ../victim/pic, $leads" path "$work/w/way1.dat" --png "$work/w/pic.png"
  victim_untouched "--png through a link"
  mkdir "$work/frames"
  ln -s ../victim/frm "$work/frames/frm001.dat"
  refused_with "frames/frm001.dat: is a symbolic link to ../victim/frm, $leads" \
    play "$data/car/car.scn" --out "$work/frames"
  victim_untouched "play --out through a link"
  [ "$(ls -A "$work/frames" | wc -l)" -eq 1 ] || fail "play --out wrote frames: $(ls -A "$work/frames")"

  # A link to a file in its own folder is written through, as before.
  echo 'old' > "$work/w/kept.keys"
  ln -s kept.keys "$work/w/inside.keys"
  "$apcs" --workdir "$work/w" --keys "$work/w/session.keys" --record "$work/w/inside.keys" --glyphs ascii \
    < /dev/null > /dev/null 2> "$work/err" || fail "--record through a link inside its folder: $(cat "$work/err")"
  [ -L "$work/w/inside.keys" ] && [ "$(cat "$work/w/kept.bak")" = old ] || fail "the link inside its folder was not written through"
}

# Fails when FILE holds a raw ESC or BEL; says what it holds.
no_raw_controls() {
  if LC_ALL=C grep -q $'[\x1B\x07]' "$2"; then
    fail "$1: raw control characters reached it: $(od -c "$2" | head -5)"
  fi
}

names() {
  setup
  local bad=$'esc\e]0;PWN2\a'
  local shown='esc\x1B]0;PWN2\x07'
  cp "$data/exercises/answers/exercise-1-tension-answer.keys" "$work/$bad.keys"
  "$apcs" grade "$data/exercises/exercise-1-tension.keys" "$work/$bad.keys" "$work/${bad}-gone.keys" \
    > "$work/grades.csv" 2> "$work/err"
  no_raw_controls "grade's stderr" "$work/err"
  no_raw_controls "grade's CSV" "$work/grades.csv"
  grep -qF "$shown-gone.keys" "$work/err" || fail "grade: the missing recording is not named escaped: $(cat "$work/err")"
  grep -qF "$shown.keys" "$work/grades.csv" || fail "grade: the CSV does not name the recording escaped: $(cat "$work/grades.csv")"

  # Each command given the name where a file or a folder is expected: refused, the name escaped.
  local missing="$work/$bad"
  local dat="$work/w/way1.dat"
  local -a commands=(
    "path|$missing.dat"
    "draw|$missing.dat|--png|$work/d.png"
    "fit|$missing.dat|$dat|$dat|$dat|--out|$work/f"
    "inbetween|$missing.dat|$dat|--out|$work/i"
    "play|$missing.scn"
    "play|$data/car/car.scn|--out|$missing/deep"
    "--workdir|$missing"
    "--workdir|$work/w|--keys|$missing-none.keys"
    "--workdir|$work/w|--keys|$work/w/session.keys|--record|$missing/x.keys"
    "--workdir|$work/w|--keys|$work/w/lesson.keys|--handout|$missing/deep"
    "path|$dat|--png|$missing/x.png"
  )
  for command in "${commands[@]}"; do
    IFS='|' read -r -a arguments <<< "$command"
    "$apcs" "${arguments[@]}" < /dev/null > "$work/out" 2> "$work/err"
    no_raw_controls "apcs ${arguments[*]}" "$work/err"
    no_raw_controls "apcs ${arguments[*]} (stdout)" "$work/out"
    grep -qF "$shown" "$work/err" || fail "apcs ${arguments[*]}: the name is not shown escaped: $(cat "$work/err")"
  done

  # A bidi override in a name is shown by its code, and one in a caption refuses the script.
  "$apcs" path "$work/gpj"$'\u202e'".dat" > /dev/null 2> "$work/err"
  grep -qF "gpjU+202E.dat" "$work/err" || fail "a bidi override in a name: $(cat "$work/err")"
  printf ';; turn \u202eleft\nENTER\n' > "$work/w/bidi.keys"
  refused_with "U+202E" --workdir "$work/w" --keys "$work/w/bidi.keys" --glyphs ascii
}

handout_folder() {
  setup
  local handout=(--workdir "$work/w" --keys "$work/w/lesson.keys" --glyphs ascii --handout)
  # The user's course page and its older version: refused, both as they were.
  mkdir "$work/mine"
  echo '<html>my course page</html>' > "$work/mine/index.html"
  echo 'my older course page' > "$work/mine/index.bak"
  refused_with "mine: holds an index.html that is not a handout's" "${handout[@]}" "$work/mine"
  [ "$(cat "$work/mine/index.html")" = '<html>my course page</html>' ] || fail "the user's index.html was replaced"
  [ "$(cat "$work/mine/index.bak")" = 'my older course page' ] || fail "the user's index.bak was replaced"
  [ "$(ls -A "$work/mine" | wc -l)" -eq 2 ] || fail "files were added to the user's folder: $(ls -A "$work/mine")"
  mkdir "$work/notes"
  echo 'mine' > "$work/notes/notes.txt"
  refused_with "notes: holds notes.txt, and no handout's index.html" "${handout[@]}" "$work/notes"
  [ "$(ls -A "$work/notes")" = notes.txt ] || fail "files were added to the user's folder: $(ls -A "$work/notes")"

  # An earlier handout is APCS's: written over; a page of an earlier, longer lesson is named, kept.
  "$apcs" "${handout[@]}" "$work/h" < /dev/null > /dev/null 2> "$work/err" || fail "first handout: $(cat "$work/err")"
  cp "$work/h/01-w-i-a-control-point-halfway.png" "$work/h/99-an-earlier-page.png"
  echo 'older' > "$work/h/99-an-earlier-page.bak"
  "$apcs" "${handout[@]}" "$work/h" < /dev/null > /dev/null 2> "$work/err" || fail "second handout: $(cat "$work/err")"
  grep -qF "h/99-an-earlier-page.png is from an earlier run (not rewritten)" "$work/err" \
    || fail "the earlier page is not named: $(cat "$work/err")"
  [ -f "$work/h/99-an-earlier-page.png" ] || fail "the earlier page was deleted"
  # A file of the user's put in it makes it theirs too.
  echo 'mine' > "$work/h/notes.txt"
  refused_with "h: holds notes.txt, which is not a file of a handout" "${handout[@]}" "$work/h"
}

swapped_folder() {
  setup
  # A scene of 30001 frames, written for long enough to swap its folder while it writes.
  sed 's/^FRAMES 60$/FRAMES 30000/' "$data/car/car.scn" > "$work/w/car.scn"
  cp "$data"/car/*.dat "$work/w/"
  mkdir "$work/other" "$work/out"
  "$apcs" play "$work/w/car.scn" --out "$work/out" < /dev/null > /dev/null 2> "$work/err" &
  local pid=$!
  local seen=
  for _ in $(seq 1 6000); do
    if [ -n "$(find "$work/out" -name 'frm*.dat' -print -quit 2>/dev/null)" ]; then
      mv "$work/out" "$work/out.moved" && ln -s other "$work/out"
      kill -0 "$pid" 2>/dev/null && seen=yes
      break
    fi
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.005
  done
  wait "$pid"; local status=$?
  [ -n "$seen" ] || fail "the folder was not swapped while play wrote (exit $status): $(cat "$work/err")"
  local strays
  strays=$(find "$work/other" -type f | wc -l)
  [ "$strays" -eq 0 ] || fail "$strays files were written into the folder put in out's place (exit $status)"
  [ "$status" -eq 0 ] || fail "exit $status: $(cat "$work/err")"
  [ "$(find "$work/out.moved" -name 'frm*.dat' | wc -l)" -eq 30001 ] || fail "the moved folder misses frames"
}

case "$case_name" in
  links) links ;;
  names) names ;;
  handout-folder) handout_folder ;;
  swapped-folder) swapped_folder ;;
  *) fail "unknown case $case_name" ;;
esac
echo "ok: $case_name"
