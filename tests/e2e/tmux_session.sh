#!/usr/bin/env bash
# End-to-end: the real apcs in a real terminal (tmux, 80x25), a whole session typed key by key.
# Usage: tmux_session.sh APCS DATA_FOLDER
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
apcs=$1
data=$2
command -v tmux >/dev/null || { echo "tmux is not installed"; exit 77; }

source "$(dirname "$0")/tmux_lib.sh"
tmux_test_folder e2e
cp "$data"/key1.dat "$data"/key2.dat "$data"/way1.dat "$data"/way4.dat "$work"/

keys() { tmux -L "$socket" send-keys -t apcs "$@"; sleep 0.15; }

tmux -L "$socket" new-session -d -s apcs -x 80 -y 25 -c "$work" \
  "LANG=C.UTF-8 '$apcs' --glyphs ascii; echo EXITED=\$?; sleep 60"

wait_for apcs "Please keyin the KEY1 filename!"
keys Enter
wait_for apcs "Please keyin the KEY2 filename!"
keys Enter
wait_for apcs "THETA ,PHI & delay-time value."
keys "0 90 40" Enter
wait_for apcs "to adjust the point's animating path!"
keys way1.dat Enter
wait_for apcs "Please input the slope : DS[0] ,DD[N]"
keys Enter
wait_for apcs "8 : Global Control"
keys 8
wait_for apcs ">TENSION"
keys 6 6
# The keypad's 6 with NumLock off, as terminals without a terminfo name for it send it: ESC O v.
tmux -L "$socket" send-keys -t apcs -l $'\eOv'
sleep 0.15
wait_for apcs "+0.15"
keys Enter
wait_for apcs ">CONTINUITY"
keys 4 Escape
wait_for apcs ">BIAS"
keys Right Enter L Enter
wait_for apcs "Adjust the path again ? (Y/N)"
keys N
wait_for apcs "Press 'Y' to adjust the next path !"
keys Y
wait_for apcs "to adjust the point's animating path!"
keys way4.dat Enter
wait_for apcs "Please input the slope"
keys "0.5 1" Enter
wait_for apcs "8 : Global Control"
keys 2
wait_for apcs "Enter picks the FIRST"
keys 6 6 Enter
wait_for apcs "Enter picks the LAST"
keys 6 Enter
wait_for apcs ">TENSION"
keys J Enter Enter Enter Enter
wait_for apcs "Adjust the path again ? (Y/N)"
keys N
wait_for apcs "Press <ENTER> to Stop the work !"
keys Enter
wait_for apcs "Press any key to draw the animation effect!"
keys Space
wait_for apcs "Press any key to see all frames"
keys Space
wait_for apcs "Press any key to end APCS"
keys Space
wait_for apcs "EXITED=0"

for file in ani1.dat ani4.dat inb001.dat inb012.dat way1.bak way4.bak apcs.log; do
  [ -s "$work/$file" ] || { echo "missing $file"; ls -l "$work"; exit 1; }
done
grep -q "^0 0 0 0.15 0 0.05 0.15$" "$work/way1.dat" || { echo "way1.dat not adjusted:"; cat "$work/way1.dat"; exit 1; }
grep -q "^-3 10 5 -0.15 0 0 0$" "$work/way4.dat" || { echo "way4.dat not adjusted:"; cat "$work/way4.dat"; exit 1; }
passed=1

# --keys with a terminal: the script's keys are typed first, then the keyboard takes over.
rm -f "$work"/ani* "$work"/inb* "$work"/*.bak "$work"/apcs.log
cp "$data"/way1.dat "$work"/way1.dat
printf 'ENTER\nENTER\nTEXT 0 90 40\nENTER\nTEXT way1.dat\nENTER\nENTER\n8\n' > "$work/start.keys"
tmux -L "$socket" new-session -d -s scripted -x 80 -y 25 -c "$work" \
  "'$apcs' --glyphs ascii --keys start.keys --record again.keys; echo EXITED=\$?; sleep 60"
wait_for scripted ">TENSION"
tmux -L "$socket" send-keys -t scripted L Enter Enter Enter Enter N
sleep 0.5
grep -q "^0 0 0 0.15 0 0 0$" "$work/way1.dat" || { echo "typed keys after the script were lost:"; cat "$work/way1.dat"; exit 1; }
# A hang-up ends the session; the keys so far are still recorded, script and typed alike.
tmux -L "$socket" kill-session -t scripted
for _ in $(seq 1 50); do [ -s "$work/again.keys" ] && break; sleep 0.1; done
grep -q "^TEXT way1.dat$" "$work/again.keys" || { echo "no record written"; exit 1; }
grep -q "L" "$work/again.keys" || { echo "typed keys not recorded"; cat "$work/again.keys"; exit 1; }
passed=$((passed + 1))
echo "$passed passed, 0 failed"
