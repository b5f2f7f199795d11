#!/usr/bin/env bash
# The Debian package, as a user meets it: built from a clean clone (scripts/package.sh; with
# --with-tests its whole test suite runs in the build, as on a Debian build daemon: CI's release
# build), lintian reports no error, `dpkg -i` installs it, and from `/` the installed program draws
# the figures into a new folder, replays an installed example's keys in a scratch copy, and
# `man apcs` shows the page; `apt-get remove apcs` takes it all away.
# Needs root (it installs a package). Usage: tests/e2e/debian_package.sh [--with-tests] [SOURCE_FOLDER]
set -uo pipefail
package_options=()
if [ "${1:-}" = --with-tests ]; then
  package_options=(--with-tests)
  shift
fi
source_tree=$(realpath "${1:-$(dirname "$0")/../..}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "needs root: it installs and removes the package"

bash "$source_tree/scripts/package.sh" "${package_options[@]}" "$work/deb" > "$work/build.log" 2>&1 ||
  fail "building the package: $(grep -E -A12 '(Failed|\*\*\*Exception|\*\*\*Timeout)' "$work/build.log" | tail -80; tail -30 "$work/build.log")"
grep -E "tests passed|tests failed" "$work/build.log"
# CI (APCS_REQUIRE_EVERY_TEST) has installed every tool the tests need: a skip there is a failure.
if [ -n "${APCS_REQUIRE_EVERY_TEST:-}" ] && grep -q "^The following tests did not run:" "$work/build.log"; then
  grep -A20 "^The following tests did not run:" "$work/build.log"
  fail "tests reported a skip (above), and APCS_REQUIRE_EVERY_TEST requires every test to run"
fi
# The package is built without -Werror (a newer compiler's new warning must not break a Debian
# build), so GCC's warnings are refused here: this is the only GCC build CI makes.
gcc_warning='warning: .*\[-W[a-zA-Z0-9=+-]+\]'
if grep -qE "$gcc_warning" "$work/build.log"; then
  grep -E -B14 -A4 "$gcc_warning" "$work/build.log"   # with the lines that say where it was inlined from
  fail "GCC warns (above)"
fi
grep -q -- "-D_FORTIFY_SOURCE=2 .*-c .*src/main.cpp" "$work/build.log" ||
  fail "CPPFLAGS (_FORTIFY_SOURCE) did not reach the compiler"
package=$(ls "$work"/deb/apcs_*.deb)

# lintian's informational tags and warnings are printed; an error fails.
lintian --fail-on error --display-info --color never "$work"/deb/apcs_*.changes 2>&1 | grep -v "root privileges"
[ "${PIPESTATUS[0]}" -eq 0 ] || fail "lintian reports an error"

dpkg -i "$package" > "$work/install.log" 2>&1 || fail "dpkg -i: $(cat "$work/install.log")"
trap 'apt-get remove -y -qq apcs > /dev/null 2>&1; rm -rf "$work"' EXIT
[ "$(command -v apcs)" = /usr/bin/apcs ] || fail "apcs is not /usr/bin/apcs: $(command -v apcs)"
for file in /usr/share/apcs/n-to-l/session.keys /usr/share/apcs/robot/robot.scn /usr/share/doc/apcs/manual.txt \
            /usr/share/doc/apcs/README.md /usr/share/doc/apcs/docs/fig-3-1-2.png /usr/share/doc/apcs/copyright \
            /usr/share/man/man1/apcs.1.gz /usr/share/bash-completion/completions/apcs /usr/share/applications/apcs.desktop; do
  [ -f "$file" ] || fail "$file is not installed"
done
grep -q '^Terminal=true$' /usr/share/applications/apcs.desktop || fail "the desktop entry does not ask for a terminal"

cd / || fail "cannot enter /"
mkdir "$work/figures"
apcs figures --out "$work/figures" > "$work/out" 2> "$work/err" || fail "apcs figures: $(cat "$work/err")"
[ -s "$work/figures/fig-3-3-3.png" ] || fail "no fig-3-3-3.png: $(cat "$work/out")"

cp -r /usr/share/apcs/n-to-l "$work/session"
apcs --keys "$work/session/session.keys" --workdir "$work/session" < /dev/null > "$work/out" 2> "$work/err" ||
  fail "apcs --keys: exit $?: $(cat "$work/err")"
[ -s "$work/session/inb001.dat" ] || fail "the session wrote no inb001.dat: $(ls "$work/session")"

# The answers are the teacher's: in the documentation's folder, not beside the exercises.
[ ! -e /usr/share/apcs/exercises/answers ] || fail "the answers are installed beside the exercises"
cp -r /usr/share/apcs/exercises "$work/ex"
apcs --keys /usr/share/doc/apcs/answers/exercise-1-tension-answer.keys --workdir "$work/ex" < /dev/null \
  > "$work/out" 2> "$work/err" || fail "the installed answer: exit $?: $(cat "$work/err")"

MANPAGER=cat MANWIDTH=80 man apcs > "$work/man" 2> "$work/err" || fail "man apcs: $(cat "$work/err")"
grep -q "Kochanek" "$work/man" || fail "man apcs shows no page: $(head "$work/man")"

apt-get remove -y -qq apcs > "$work/remove.log" 2>&1 || fail "apt-get remove: $(cat "$work/remove.log")"
trap 'rm -rf "$work"' EXIT
[ ! -e /usr/bin/apcs ] && [ ! -e /usr/share/apcs ] || fail "apt-get remove left files behind"
echo "passed: built, lintian without error, installed, figures, a session, the answers apart, man apcs, removed"
