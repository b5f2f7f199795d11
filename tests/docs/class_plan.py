#!/usr/bin/env python3
"""Manual section 25's 45-minute class, held against the program.

Every line "PRESS SCRIPT [OPTIONS] KEY×N ..." of the section is one lesson or exercise of the plan.
This script
  - sums the presses (at most 120: a presenter's remote, not a keyboard),
  - times the plan at 30 s a caption plus each animation's length (frames × delay, read from the
    apcs.log of a headless run with the same options): at most 45 minutes,
  - plays each script in tmux at 80x24 (--pace step, the glyph set given) on a fresh copy of its
    folder with exactly those presses, and requires that every caption was shown and that the last
    press leaves "End of the script" on the caption row.

Usage: class_plan.py APCS MANUAL DATA_FOLDER [GLYPHS [SCREENS_FOLDER]]   (prints each script's presses,
captions and time; SCREENS_FOLDER gets SCRIPT.txt, every screen the class saw, for reading them)
"""
import concurrent.futures
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

MOST_PRESSES = 120
MOST_SECONDS = 45 * 60
SECONDS_A_CAPTION = 30
SKIPPED = "(skipped) "
END_OF_SCRIPT = "End of the script: the keyboard is yours"
TMUX_KEYS = {"PgDn": "NPage", "PgUp": "PPage", "Home": "Home", "Space": "Space"}


def plan_lines(manual):
    text = open(manual, encoding="utf-8").read()
    start = text.index("25. TEACHING WITH APCS")
    section = text[start:text.index("\n26. ", start)]
    return [line.split()[1:] for line in section.split("\n") if line.strip().startswith("PRESS ")]


def parse(words):
    """SCRIPT, its options, and the presses as tmux key names in order."""
    script, options, presses = words[0], [], []
    rest = words[1:]
    while rest and rest[0].startswith("--"):
        options += rest[:2]
        rest = rest[2:]
    for word in rest:
        key, _, count = word.partition("×")
        if key not in TMUX_KEYS:
            sys.exit(f"class_plan: {script}: '{word}' is no key of the plan; expected {', '.join(TMUX_KEYS)}")
        presses += [TMUX_KEYS[key]] * (int(count) if count else 1)
    return script, options, presses


def script_folder(data, script):
    for folder in sorted(os.listdir(data)):
        if os.path.isfile(os.path.join(data, folder, script)):
            return os.path.join(data, folder)
    sys.exit(f"class_plan: {script}: not found in {data}/*/")


def captions_of(path):
    """The script's captions; a task (the caption a GOAL line follows) stays on the caption row while
    its goal waits, the goal's feedback on the message line."""
    lines = [line.strip() for line in open(path, encoding="utf-8") if line.strip() and not line.startswith("; ")]
    return [line[2:].strip() for line in lines if line.startswith(";;")]


def animation_seconds(apcs, folder, script, options):
    """The animations' length as the class sees them: frames × delay, from apcs.log."""
    with tempfile.TemporaryDirectory() as work:
        shutil.copytree(folder, work, dirs_exist_ok=True)
        subprocess.run([apcs, "--keys", script, *options], cwd=work, stdin=subprocess.DEVNULL,
                       capture_output=True, text=True, timeout=120)
        log = open(os.path.join(work, "apcs.log"), encoding="utf-8").read()
    return sum(int(frames) * int(ms) / 1000 for frames, ms in re.findall(r"animation: (\d+) frames, (\d+) ms each", log))


# The scripts are played side by side, each in a tmux server of its own (SOCKET-N): one script's
# server ending cannot take another's session, nor another test's server this plan's. A play mostly
# waits for its screen to settle: four at once, the longest first (62 s against 117 s one by one).
SOCKET = f"apcs-class-plan-{os.getpid()}"
PLAYS_AT_ONCE = 4
local = threading.local()


def tmux(*args):
    return subprocess.run(["tmux", "-L", local.socket, *args], capture_output=True, text=True).stdout


def children_of(pid):
    children = []
    for entry in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{entry}/stat", encoding="utf-8") as stat:
                parent = int(stat.read().rsplit(")", 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue
        if parent == pid:
            children.append(int(entry))
    return children


def end_program(session):
    """Ends the program with SIGTERM, as a user's `kill` would, and waits for it to go before the
    server does. Killing the server under a running program hangs up its terminal, and the hang-up's
    SIGCONT can erase the SIGSTOP with which LeakSanitizer stops the exiting program's threads: the
    sanitizer build's program then spins at exit for ever (three such were found eating two cores)."""
    shell = tmux("list-panes", "-t", session, "-F", "#{pane_pid}").strip()
    if not shell.isdigit():
        return None
    for pid in children_of(int(shell)):
        os.kill(pid, signal.SIGTERM)
        deadline = time.time() + 30
        while os.path.exists(f"/proc/{pid}") and time.time() < deadline:
            time.sleep(0.05)
        if os.path.exists(f"/proc/{pid}"):
            os.kill(pid, signal.SIGKILL)
            return f"the program (pid {pid}) did not end within 30 s of SIGTERM"
    return None


def changed_screen(session, before, most_seconds=10):
    """Waits until the pane differs from `before`: a loaded machine may take longer than the quiet
    time to answer a key, and the screen before the key must not pass for the screen after it."""
    deadline = time.time() + most_seconds
    while time.time() < deadline:
        if tmux("capture-pane", "-p", "-t", session) != before:
            return
        time.sleep(0.05)


def shown_as(caption, row):
    """Whether the caption row `row` shows `caption`: as it is, or as a goal skipped by PgDn marks
    the caption that closes it ("(skipped) ...", cut at the screen's edge)."""
    if row == caption:
        return True
    return row.startswith(SKIPPED) and len(row) > len(SKIPPED) and caption.startswith(row[len(SKIPPED):])


def caption_row(screen):
    return screen.rstrip("\n").split("\n")[-1].strip()


def settled_screen(session, quiet, seen):
    """The pane once it has not changed for `quiet` seconds (the replay plays a PgDn's keys at once;
    an animation changes the pane once a frame, so a presenter waits for its end). Every caption
    row on the way is added to `seen`: on a loaded machine a step's screens may stand longer than
    the quiet time before the replay reaches its caption."""
    screen, since = tmux("capture-pane", "-p", "-t", session), time.time()
    seen.add(caption_row(screen))
    deadline = time.time() + 120
    while time.time() < deadline:
        time.sleep(0.1)
        now = tmux("capture-pane", "-p", "-t", session)
        seen.add(caption_row(now))
        if now != screen:
            screen, since = now, time.time()
        elif time.time() - since > quiet:
            return screen
    return screen


def first_caption_screen(session):
    """Waits until the replay has played its preamble and stands at its first caption (the badge
    says "caption 0 of N"), up to 30 s."""
    deadline = time.time() + 30
    while time.time() < deadline:
        if "caption 0 of" in tmux("capture-pane", "-p", "-t", session).split("\n")[0]:
            return
        time.sleep(0.05)


def quiet_seconds(options):
    """How long a screen must stand still to count as settled: longer than an animation's frame."""
    delay = options[options.index("--delay") + 1] if "--delay" in options else "100"
    return max(0.8, int(delay) / 1000 + 0.5)


def play(apcs, folder, script, options, presses, glyphs, shown):
    """The captions the class saw, the caption row after the last press, and what went wrong in
    ending the program (or None); `shown` gets each screen after a press, under the press."""
    session = "class-plan"
    with tempfile.TemporaryDirectory() as work:
        shutil.copytree(folder, work, dirs_exist_ok=True)
        command = " ".join([apcs, "--keys", script, "--pace", "step", "--glyphs", glyphs, *options])
        tmux("kill-session", "-t", session)
        tmux("new-session", "-d", "-s", session, "-x", "80", "-y", "24", "-c", work,
             f"LANG=C.UTF-8 {command}; sleep 60")
        seen = set()
        quiet = quiet_seconds(options)
        try:
            first_caption_screen(session)
            screen = settled_screen(session, quiet, seen)
            shown.append(f"=== {script}: the replay begins\n{screen}")
            for number, key in enumerate(presses, 1):
                tmux("send-keys", "-t", session, key)
                changed_screen(session, screen)
                screen = settled_screen(session, quiet, seen)
                shown.append(f"=== {script}: press {number}, {key}\n{screen}")
        finally:
            ending = end_program(session)
            tmux("kill-server")
    return seen, caption_row(screen), ending


def hold(apcs, data, glyphs, number, words):
    """One line of the plan played: its script, presses, captions, seconds and what was seen."""
    local.socket = f"{SOCKET}-{number}"
    script, options, presses = parse(words)
    folder = script_folder(data, script)
    captions = captions_of(os.path.join(folder, script))
    seconds = SECONDS_A_CAPTION * len(captions) + animation_seconds(apcs, folder, script, options)
    shown = []
    seen, last_row, ending = play(apcs, folder, script, options, presses, glyphs, shown)
    return script, presses, captions, seconds, shown, seen, last_row, ending


def main():
    apcs, manual, data = sys.argv[1:4]
    glyphs = sys.argv[4] if len(sys.argv) > 4 else "ascii"
    screens_folder = sys.argv[5] if len(sys.argv) > 5 else None
    total_presses, total_seconds, failures = 0, 0.0, []
    lines = plan_lines(manual)
    if not lines:
        sys.exit("class_plan: manual section 25 has no PRESS line")
    # The longest plays (most presses, each waiting the longest quiet) start first.
    def waits(number):
        _, options, presses = parse(lines[number])
        return len(presses) * quiet_seconds(options)
    order = sorted(range(len(lines)), key=waits, reverse=True)
    with concurrent.futures.ThreadPoolExecutor(PLAYS_AT_ONCE) as plays:
        held = {number: plays.submit(hold, apcs, data, glyphs, number, lines[number]) for number in order}
        results = [held[number].result() for number in range(len(lines))]
    for script, presses, captions, seconds, shown, seen, last_row, ending in results:
        if screens_folder:
            os.makedirs(screens_folder, exist_ok=True)
            with open(os.path.join(screens_folder, script + ".txt"), "w", encoding="utf-8") as out:
                out.write("\n".join(shown))
        unseen = [caption for caption in captions if not any(shown_as(caption, row) for row in seen)]
        print(f"{script}: {len(presses)} presses, {len(captions)} captions, {seconds:.0f} s; "
              f"last caption row: {last_row}")
        if unseen:
            failures.append(f"{script}: captions never shown with those presses: {unseen}; "
                            f"the caption rows seen: {sorted(seen)}")
        if not last_row.startswith(END_OF_SCRIPT):
            failures.append(f"{script}: the presses end at '{last_row}', not at the end of the script")
        if ending:
            failures.append(f"{script}: {ending}")
        total_presses += len(presses)
        total_seconds += seconds
    print(f"the plan: {total_presses} presses, {total_seconds / 60:.1f} minutes")
    if total_presses > MOST_PRESSES:
        failures.append(f"{total_presses} presses; expected at most {MOST_PRESSES}")
    if total_seconds > MOST_SECONDS:
        failures.append(f"{total_seconds / 60:.1f} minutes; expected at most 45")
    for failure in failures:
        print("FAILED: " + failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
