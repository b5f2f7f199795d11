#!/usr/bin/env python3
"""A terminal that answers --pixels' device-attributes question with its reply and a flood of more
bytes in the same write (type-ahead, a paste, a terminal answering garbage), then asks APCS to end
with keys alone (no signal): APCS must end, never spin (issue 45, item 1: 137 bytes had hung it).

Usage: pixel_flood.py APCS DATA_FOLDER session|play EXTRA_BYTES
  session  `apcs --pixels sixel` at the KEY1 prompt; the flood is the letter a, typed into the
           filename field; then Esc (clears the field, if any a came), Esc (asks to quit), y.
  play     `apcs play snake-apple.scn --pixels sixel`; the flood is the letter a (no key of the
           player's); then q.
Exit 0 when APCS ended with status 0 within 30 s of the quitting keys (an ASan build takes its time over 10,000 keys), else 1 with what it showed."""
import fcntl
import os
import select
import struct
import subprocess
import sys
import termios
import time

apcs, data, mode, extra = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3], int(sys.argv[4])
master, slave = os.openpty()
fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 80, 720, 360))
environment = dict(os.environ, TERM="xterm", LANG="C.UTF-8", LC_ALL="C.UTF-8")
for name in ("TMUX", "STY"):
    environment.pop(name, None)


def controlling_terminal():
    os.setsid()
    fcntl.ioctl(0, termios.TIOCSCTTY, 0)


if mode == "session":
    command = [apcs, "--glyphs", "ascii", "--pixels", "sixel"]
    quitting = [b"\x1b"]
else:
    command = [apcs, "play", os.path.join(data, "snake-apple", "snake-apple.scn"), "--glyphs", "ascii",
               "--pixels", "sixel"]
    quitting = [b"q"]
child = subprocess.Popen(command, cwd=data, stdin=slave, stdout=slave, stderr=slave, env=environment,
                         preexec_fn=controlling_terminal)
os.close(slave)
shown = b""
answered = []


def read_for(seconds):
    """Reads what APCS writes for `seconds` (keeping the pty drained); False once it has closed."""
    global shown
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        ready, _, _ = select.select([master], [], [], 0.05)
        if not ready:
            continue
        try:
            chunk = os.read(master, 65536)
        except OSError:
            return False
        if not chunk:
            return False
        shown = (shown + chunk)[-4000:]
        if b"\x1b[c" in chunk:
            os.write(master, b"\x1b[?62;4;22c" + b"a" * extra)
            answered.append(True)
    return True


def read_until(wanted, limit=20.0):
    """Reads until `wanted()` holds and APCS has then been quiet 0.4 s, or `limit` seconds: a loaded
    machine (CI building beside the tests) can keep APCS from answering for longer than 0.4 s, and a
    key sent before APCS has read the one before it could reach ncurses as Alt and a letter."""
    end = time.monotonic() + limit
    while time.monotonic() < end:
        before = len(answered), shown
        if not read_for(0.4):
            return
        if wanted() and (len(answered), shown) == before:
            return


def fail(reason):
    print(f"FAILED ({mode}, {extra} bytes): {reason}; last output: {shown[-600:]!r}")
    child.kill()
    sys.exit(1)


read_until(lambda: answered)
for key in quitting:
    written = shown
    os.write(master, key)
    read_until(lambda: shown != written)
if mode == "session":
    if b"Quit APCS" not in shown:
        os.write(master, b"\x1b")
        read_until(lambda: b"Quit APCS" in shown)
    os.write(master, b"y")
end = time.monotonic() + 30
while child.poll() is None and time.monotonic() < end:
    read_for(0.1)
if child.poll() is None:
    fail("APCS did not end on its quitting keys")
if child.returncode != 0:
    fail(f"APCS ended with status {child.returncode}")
print(f"passed ({mode}, {extra} bytes)")
