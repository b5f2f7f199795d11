#!/usr/bin/env bash
# The bash completion offers the commands, each command's options as its --help lists them, the
# values of --glyphs and --spacing, and only the files an option takes.
# Usage: completion.sh COMPLETION_SCRIPT APCS
set -uo pipefail
script=$1
apcs=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

# shellcheck source=/dev/null
source "$script" || fail "cannot source $script"
complete -p apcs > /dev/null 2>&1 || fail "$script registers no completion for apcs"

# Completes the command line "$@" (the last word is the one being typed), sorted, one line.
completions()
{
    COMP_WORDS=("$@")
    COMP_CWORD=$(($# - 1))
    COMP_LINE="$*"
    COMP_POINT=${#COMP_LINE}
    COMPREPLY=()
    _apcs
    printf '%s\n' "${COMPREPLY[@]}" | LC_ALL=C sort | tr '\n' ' ' | sed 's/ $//'
}

expect() { # expected, then the command line
  local expected=$1; shift
  local got
  got=$(completions "$@")
  [ "$got" = "$expected" ] || fail "'$*': expected '$expected', got '$got'"
}

expect "figures fit" apcs "fi"
expect "blocks braille" apcs --glyphs b
expect "always auto" apcs --color a
expect "sixel" apcs --pixels s
expect "blocks braille" apcs path a.dat --glyphs b
expect "exact nearest" apcs fit --spacing ""
expect "front" apcs --view fr
expect "--phi --png --png-raw --print" apcs path --p
expect "--out" apcs fit --o
expect "" apcs path --o
expect "--delay" apcs --de
expect "--frames" apcs inbetween --fr
expect "" apcs path --fr
expect "--gif" apcs inbetween --g
expect "" apcs path --g

# Every command's options, as its --help lists them.
for command in "" path inbetween fit export draw play figures; do
  # shellcheck disable=SC2086
  listed=$("$apcs" $command --help | sed '/^Examples/,$d' | grep -o -- '--[a-z][a-z-]*' | LC_ALL=C sort -u | tr '\n' ' ' | sed 's/ $//')
  [ -n "$listed" ] || fail "apcs $command --help lists no option"
  # shellcheck disable=SC2086
  expect "$listed" apcs $command --
done

cd "$work" || fail "cannot enter $work"
mkdir folder
touch key1.dat key2.dat session.keys notes.txt shot.png frames.gif
expect "folder key1.dat key2.dat" apcs fit ""
expect "folder session.keys" apcs --keys ""
expect "folder shot.png" apcs path key1.dat --png ""
expect "folder" apcs figures --out ""
expect "draw" apcs dr
expect "export" apcs ex
expect "frames tcb" apcs export way1.dat --sif-motion ""
touch path.sif
expect "folder path.sif" apcs export key1.dat --sif ""
expect "folder key1.dat key2.dat path.sif" apcs path ""
expect "folder frames.gif" apcs fit a b c d --gif ""
echo "passed: 24 completions and the options of 7 commands"
