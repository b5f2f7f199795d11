#!/usr/bin/env python3
"""Prints the largest sixel picture the terminal on standard input shows now, as WIDTH HEIGHT
(xterm's XTSMGRAPHICS: ESC [ ? 2 ; 1 ; 0 S is answered ESC [ ? 2 ; 0 ; W ; H S), or 0 0 where it
does not say within a second (its answer to the device attributes, asked after, ends the wait)."""
import os
import re
import select
import sys
import termios
import time
import tty

terminal = sys.stdin.fileno()
saved = termios.tcgetattr(terminal)
tty.setraw(terminal)
try:
    os.write(terminal, b"\x1b[?2;1;0S\x1b[c")
    got = b""
    end = time.monotonic() + 1
    while time.monotonic() < end and not re.search(rb"\x1b\[\?[0-9;]*c", got):
        ready, _, _ = select.select([terminal], [], [], 0.1)
        if ready:
            got += os.read(terminal, 1024)
finally:
    termios.tcsetattr(terminal, termios.TCSADRAIN, saved)
size = re.search(rb"\x1b\[\?2;0;([0-9]+);([0-9]+)S", got)
print(f"{int(size.group(1))} {int(size.group(2))}" if size else "0 0")
