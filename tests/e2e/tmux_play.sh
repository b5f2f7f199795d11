#!/usr/bin/env bash
# apcs play on a real terminal (tmux, 80x24, ascii): the frames play with their number on the
# message line; Space pauses; ? shows the keys until a key; P writes apcs001.png (never through a
# name that is taken, even by a dangling link); Esc stops; a key shows all frames overlaid; another
# ends it; q quits at once. Usage: tmux_play.sh APCS DATA_FOLDER
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder play

start_80x24 bike "$apcs play $data/bicycle/bicycle.scn --glyphs ascii --delay 60"
wait_for bike "of 72: bicycle.scn"
keys_to bike Space
wait_for bike "(paused)"
paused=$(screen bike | grep -o "Frame [0-9]* of 72")
sleep 0.5
[ "$(screen bike | grep -o "Frame [0-9]* of 72")" = "$paused" ] || fail_showing "the frame moved while paused" bike
keys_to bike '?'
wait_for bike "APCS help - the keys of playing a scene"
keys_to bike x
wait_for bike "(paused)"
ln -s "$work/nowhere" "$work/apcs001.png"
keys_to bike P
wait_for bike "wrote apcs002.png"
[ -L "$work/apcs001.png" ] && [ ! -e "$work/nowhere" ] || fail_showing "P wrote through a link" bike
[ "$(head -c 4 "$work/apcs002.png" | tail -c 3)" = PNG ] || fail_showing "apcs002.png is not a PNG" bike
keys_to bike Escape
wait_for bike "Press any key to see all frames"
keys_to bike x
wait_for bike "Press any key to end APCS"
keys_to bike x
wait_for bike "EXITED=0"

start_80x24 car "$apcs play $data/car/car.scn --glyphs ascii"
wait_for car "Frame "
keys_to car q
wait_for car "EXITED=0"
echo "tmux_play: plays, pauses, stops, overlays and quits"
