#!/usr/bin/env python3
"""The session with --pixels on a pseudo-terminal that this script plays the terminal of (no X, no
tmux): it answers the questions of --pixels as a terminal of its MODE would and types keys, and
counts the bytes the session writes after each key.

Usage: pixel_pty.py APCS WORKDIR MODE [STAFF_KEYS]
  MODE sixel   answers device attributes with 4 (sixel), gives the cell size (9x15 pixels) in
               TIOCGWINSZ, ignores the kitty query (as xterm -ti vt340 does); --pixels auto.
  MODE silent  answers nothing (a terminal that does not know the questions); --pixels sixel.
  MODE nopixel answers device attributes without 4 and no kitty; --pixels auto.
Runs the session at 80x24 with --keys WORKDIR/path.keys (which must end on the path screen's staff),
types STAFF_KEYS (default 6) '6' keys, one when the screen has been quiet for 0.4 s, then ends it
with SIGTERM. Prints, per line, `first-screen BYTES PICTURE_BYTES MS` and then
`key N BYTES PICTURE_BYTES` (PICTURE_BYTES: inside sixel DCS strings), and `notice TEXT` when the
screen says "pixels off: ...". Exit 0, or 1 with a reason."""
import fcntl
import os
import re
import select
import signal
import struct
import subprocess
import sys
import termios
import time

apcs, workdir, mode = sys.argv[1], sys.argv[2], sys.argv[3]
staff_keys = int(sys.argv[4]) if len(sys.argv) > 4 else 6
columns, rows, cell_width, cell_height = 80, 24, 9, 15

master, slave = os.openpty()
pixels = (columns * cell_width, rows * cell_height) if mode == "sixel" else (0, 0)
fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", rows, columns, *pixels))
choice = {"sixel": "auto", "silent": "sixel", "nopixel": "auto"}[mode]
environment = dict(os.environ, TERM="xterm", LANG="C.UTF-8", LC_ALL="C.UTF-8")
for name in ("TMUX", "STY"):
    environment.pop(name, None)


def controlling_terminal():
    os.setsid()
    fcntl.ioctl(0, termios.TIOCSCTTY, 0)


started = time.monotonic()
child = subprocess.Popen([apcs, "--glyphs", "ascii", "--pixels", choice, "--keys", "path.keys"], cwd=workdir,
                         stdin=slave, stdout=slave, stderr=slave, env=environment, preexec_fn=controlling_terminal)
os.close(slave)

attributes = {"sixel": b"\x1b[?63;1;2;4;6;9;15;22c", "silent": None, "nopixel": b"\x1b[?62;1;6;22c"}[mode]


def read_until_quiet(quiet=0.4, limit=20.0):
    """What the session writes until it has been quiet `quiet` seconds, answering its questions."""
    got = b""
    end = time.monotonic() + limit
    while time.monotonic() < end:
        ready, _, _ = select.select([master], [], [], quiet)
        if not ready:
            return got
        try:
            chunk = os.read(master, 65536)
        except OSError:
            return got
        if not chunk:
            return got
        got += chunk
        if attributes is not None:
            for _ in range(chunk.count(b"\x1b[c")):
                os.write(master, attributes)
    return got


def picture_bytes(output):
    return sum(len(m.group(0)) for m in re.finditer(rb"\x1bP[^\x1b]*\x1b\\", output, re.S))


def fail(reason):
    print("FAILED: " + reason)
    child.kill()
    sys.exit(1)


first = read_until_quiet()
first_ms = round((time.monotonic() - started) * 1000)
print(f"first-screen {len(first)} {picture_bytes(first)} {first_ms}")
notice = re.search(rb"pixels off: [ -~]*", first)
if notice:
    print("notice " + notice.group(0).decode().rstrip())
if b"TENSION" not in first:
    fail("the path screen's staff did not come: " + repr(first[-300:]))
for key in range(1, staff_keys + 1):
    os.write(master, b"6")
    output = read_until_quiet()
    print(f"key {key} {len(output)} {picture_bytes(output)}")
child.send_signal(signal.SIGTERM)
try:
    child.wait(timeout=5)
except subprocess.TimeoutExpired:
    fail("the session did not end on SIGTERM")
sys.exit(0)
