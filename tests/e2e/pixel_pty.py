#!/usr/bin/env python3
"""The session with --pixels on a pseudo-terminal that this script plays the terminal of (no X, no
tmux): it answers the questions of --pixels as a terminal of its MODE would and types keys, and
counts the bytes the session writes after each key.

Usage: pixel_pty.py APCS WORKDIR MODE [STAFF_KEYS]
  MODE sixel   answers device attributes with 4 (sixel), gives the cell size (9x15 pixels) in
               TIOCGWINSZ, ignores the kitty query (as xterm -ti vt340 does); --pixels auto.
  MODE silent  answers nothing (a terminal that does not know the questions); --pixels sixel.
  MODE nopixel answers device attributes without 4 and no kitty; --pixels auto.
  MODE csi16   as sixel, but TIOCGWINSZ has no pixels: answers CSI 16 t with 9x15 cells.
  MODE nocell  as sixel, but TIOCGWINSZ has no pixels and CSI 16 t goes unanswered.
  MODE late    answers device attributes with 4, but 0.3 s late (after the 100 ms limit): the
               answer reaches the session as input, where it must be dropped; --pixels sixel.
  MODE kitty   answers the kitty query OK and device attributes without 4, gives the cell size
               (9x15) in TIOCGWINSZ (as kitty does); --pixels auto.
Runs the session at 80x24 with --keys WORKDIR/path.keys (which must end on the path screen's staff),
types STAFF_KEYS (default 6) '6' keys, one when the screen has been quiet for 0.4 s, then Ctrl-L,
makes the window 100x30, then ends it with SIGTERM. Prints, per line, `first-screen BYTES PICTURE_BYTES MS`, `pictures BYTES…` (each picture sent
with the first screens, whole or band), and then
`key N BYTES PICTURE_BYTES` (PICTURE_BYTES: inside sixel DCS or kitty APC strings), after them
`redraw BYTES PICTURE_BYTES` for a Ctrl-L (the whole screen and picture again), `resize BYTES
PICTURE_BYTES WIDTHxHEIGHT` for the window made 100x30 (the sixel picture's size), and `notice TEXT`
when the screen says "pixels off: ...". Exit 0, or 1 with a reason."""
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

apcs, workdir, mode = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
staff_keys = int(sys.argv[4]) if len(sys.argv) > 4 else 6
columns, rows, cell_width, cell_height = 80, 24, 9, 15

master, slave = os.openpty()
pixels = (columns * cell_width, rows * cell_height) if mode in ("sixel", "kitty") else (0, 0)
fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", rows, columns, *pixels))
choice = {"sixel": "auto", "silent": "sixel", "nopixel": "auto", "kitty": "auto", "late": "sixel", "csi16": "sixel",
          "nocell": "sixel"}[mode]
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

attributes = {"sixel": b"\x1b[?63;1;2;4;6;9;15;22c", "silent": None, "nopixel": b"\x1b[?62;1;6;22c",
              "kitty": b"\x1b[?62;c", "late": b"\x1b[?63;1;2;4;6;9;15;22c", "csi16": b"\x1b[?63;1;2;4;6;9;15;22c",
              "nocell": b"\x1b[?63;1;2;4;6;9;15;22c"}[mode]


def read_until_quiet(quiet=0.4, limit=20.0, until=b""):
    """What the session writes until it has written something containing `until` and then been
    quiet `quiet` seconds, answering its questions. A loaded machine (CI builds beside the tests)
    can hold the session back longer than `quiet` before its first byte or between two screens of
    one replay, so the wait for those is `limit`, not `quiet`."""
    got = b""
    end = time.monotonic() + limit
    while time.monotonic() < end:
        answered = got and until in got
        ready, _, _ = select.select([master], [], [], quiet if answered else max(0.0, end - time.monotonic()))
        if not ready:
            return got
        try:
            chunk = os.read(master, 65536)
        except OSError:
            return got
        if not chunk:
            return got
        got += chunk
        if mode == "csi16" and b"\x1b[16t" in chunk:
            os.write(master, b"\x1b[6;%d;%dt" % (cell_height, cell_width))
        if mode == "kitty" and b"\x1b_Gi=31," in chunk:
            os.write(master, b"\x1b_Gi=31;OK\x1b\\")
        if attributes is not None:
            for _ in range(chunk.count(b"\x1b[c")):
                if mode == "late":
                    time.sleep(0.3)
                os.write(master, attributes)
    return got


def picture_bytes(output):
    return sum(len(m.group(0)) for m in re.finditer(rb"\x1b[P_][^\x1b]*\x1b\\", output, re.S))


def fail(reason):
    print("FAILED: " + reason)
    child.kill()
    sys.exit(1)


first = read_until_quiet(until=b"TENSION")
first_ms = round((time.monotonic() - started) * 1000)
print(f"first-screen {len(first)} {picture_bytes(first)} {first_ms}")
# Each picture of the first screens: the whole one, then the bands of the replay's last keys.
print("pictures " + " ".join(str(len(m.group(0))) for m in re.finditer(rb"\x1b\[[0-9;]*H\x1b[P_].*?(?=\x1b8)", first, re.S)))
notice = re.search(rb"pixels off: [ -~]*", first)
if notice:
    print("notice " + notice.group(0).decode().rstrip())
if b"TENSION" not in first:
    fail("the path screen's staff did not come: " + repr(first[-300:]))
for key in range(1, staff_keys + 1):
    os.write(master, b"6")
    output = read_until_quiet()
    print(f"key {key} {len(output)} {picture_bytes(output)}")
# Ctrl-L repaints the whole screen: the whole picture of the last key's screen.
os.write(master, b"\x0c")
output = read_until_quiet()
print(f"redraw {len(output)} {picture_bytes(output)}")
# What the repainted screen says of the staff: each line's value, in the order drawn.
print("staff " + " ".join(v.decode() for v in re.findall(rb"[+-][01]\.[0-9][0-9]", output)))
# A larger window (100x30 cells, the pixels to match): the whole picture again, at its new size.
fcntl.ioctl(master, termios.TIOCSWINSZ, struct.pack("HHHH", 30, 100, *(100 * cell_width, 30 * cell_height) if any(pixels) else (0, 0)))
# (Setting the size sends the session SIGWINCH, as a terminal's resize does.)
output = read_until_quiet()
size = re.search(rb"\x1bP0;1;0q\"1;1;([0-9]+);([0-9]+)", output)
print(f"resize {len(output)} {picture_bytes(output)} {size.group(1).decode() + 'x' + size.group(2).decode() if size else '-'}")
child.send_signal(signal.SIGTERM)
try:
    child.wait(timeout=5)
except subprocess.TimeoutExpired:
    fail("the session did not end on SIGTERM")
sys.exit(0)
