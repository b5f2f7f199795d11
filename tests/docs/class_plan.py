#!/usr/bin/env python3
"""Manual section 25's 45-minute class, held against the program.

Every line "PRESS SCRIPT [OPTIONS] KEY×N ..." of the section is one lesson or exercise of the plan.
This script
  - sums the PgDn presses: at most 40 (a presenter's remote, not a keyboard),
  - times the plan: 0.75 minute a caption, 1/3 minute a command typed during the class
    (an indented "apcs" line between "The class, minute by minute" and "After the class"), 1.75
    a figure shown (each fig-*.png named there), 2 a GOAL of the scripts played, the hands-on
    minutes the section states ("hands-on: N minutes"), and each animation's length (frames ×
    delay, read from the apcs.log of a headless run with the same options): at most 45 minutes,
  - plays each script in a real 80x23 pane (tmux on an 80x24 window, its status line on; the pane's
    height is checked) with --pace step and the glyph set given, on a fresh copy of its folder, with
    exactly those presses, and requires that every caption was shown and that the last press leaves
    "End of the script" on the caption row,
  - plays each script again in an 80x24 pane and requires that after PgDn K every row below the
    badge's is the handout's page K (apcs --handout with the same options and glyphs), an exercise's
    task with its goal's feedback; past a goal the class skips (PgDn), which the handout's headless
    run finds not reached, only the verdict's words differ (pairs).

Usage: class_plan.py APCS MANUAL DATA_FOLDER [GLYPHS [SCREENS_FOLDER]]   (prints each script's presses,
captions and minutes; SCREENS_FOLDER gets SCRIPT.txt, every screen the class saw, for reading them)
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

MOST_PAGE_DOWNS = 40
MOST_MINUTES = 45
MINUTES_A_CAPTION = 0.75
MINUTES_A_COMMAND = 1 / 3
MINUTES_A_FIGURE = 1.75
MINUTES_A_GOAL = 2
PANE = (80, 23)
SKIPPED = "(skipped) "
END_OF_SCRIPT = "End of the script: the keyboard is yours"
TMUX_KEYS = {"PgDn": "NPage", "PgUp": "PPage", "Home": "Home", "Space": "Space"}


def class_section(manual):
    """Section 25's minute-by-minute part: what is done while the class watches."""
    text = open(manual, encoding="utf-8").read()
    start = text.index("25. TEACHING WITH APCS")
    section = text[start:text.index("\n26. ", start)]
    return section[section.index("The class, minute by minute"):section.index("After the class")]


def plan_lines(manual):
    return [line.split()[1:] for line in class_section(manual).split("\n") if line.strip().startswith("PRESS ")]


def fixed_minutes(manual):
    """The commands typed, the figures shown and the hands-on minutes the class part states."""
    part = class_section(manual)
    commands = sum(1 for line in part.split("\n") if re.match(r"\s+apcs ", line))
    figures = len(set(re.findall(r"fig-[0-9-]+\.png", part)))
    hands_on = sum(int(minutes) for minutes in re.findall(r"hands-on:\s+(\d+)\s+minutes?", part))
    return commands, figures, hands_on


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


def goals_of(path):
    return sum(1 for line in open(path, encoding="utf-8") if line.startswith("GOAL "))


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


def uncut(row):
    """A caption row's text without the "..." that ends a caption cut at the row's edge."""
    row = row.rstrip()
    return row[:-3] if row.endswith("...") else row


def shown_as(caption, row):
    """Whether the caption row `row` shows `caption`: as it is, or as a goal skipped by PgDn marks
    the caption that closes it ("(skipped) ...", ending in "..." where the row cuts it)."""
    if row == caption:
        return True
    return row.startswith(SKIPPED) and len(row) > len(SKIPPED) and caption.startswith(uncut(row[len(SKIPPED):]))


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


def open_pane(session, work, command, size):
    """A tmux session whose one pane is `size` and runs `command` in `work`; 80x23 is made as a class
    has it: an 80x24 client attached (through `script`, which gives it a terminal of that size)
    under tmux's status line. Returns the client's process (or None) and what went wrong (or None)."""
    columns, rows = size
    attached = rows == PANE[1]
    window_rows = rows + 1 if attached else rows
    tmux("new-session", "-d", "-s", session, "-x", str(columns), "-y", str(window_rows), "-c", work, "sleep 600")
    client = None
    wanted_client = ""
    if attached:
        tmux("set-option", "-t", session, "status", "on")
        client = subprocess.Popen(["script", "-qfc", f"stty rows {window_rows} cols {columns}; exec tmux -L "
                                   f"{local.socket} attach -t {session}", "/dev/null"],
                                  stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        wanted_client = f"{columns}x{window_rows}"
    deadline = time.time() + 10
    shown = ""
    while time.time() < deadline:
        clients = tmux("list-clients", "-t", session, "-F", "#{client_width}x#{client_height}").split()
        shown = tmux("display", "-p", "-t", session, "#{pane_width}x#{pane_height}").strip()
        if shown == f"{columns}x{rows}" and (not attached or clients == [wanted_client]):
            tmux("respawn-pane", "-k", "-t", session, "-c", work, f"LANG=C.UTF-8 {command}; sleep 60")
            return client, None
        time.sleep(0.05)
    return client, f"the pane is {shown}, not {columns}x{rows}" + (f" under an {wanted_client} client" if attached else "")


def play(apcs, folder, script, options, presses, glyphs, shown, size=PANE, pages=None):
    """The captions the class saw, the caption row after the last press, and what went wrong (or
    None); `shown` gets each screen after a press, under the press. With `pages` (a handout's
    .txt pages, page K at index K-1), each screen after press K must be page K below the badge's row."""
    session = "class-plan"
    with tempfile.TemporaryDirectory() as work:
        shutil.copytree(folder, work, dirs_exist_ok=True)
        command = " ".join([apcs, "--keys", script, "--pace", "step", "--glyphs", glyphs, *options])
        tmux("kill-session", "-t", session)
        client, trouble = open_pane(session, work, command, size)
        seen = set()
        quiet = quiet_seconds(options)
        screen = ""
        try:
            if trouble is None:
                first_caption_screen(session)
                screen = settled_screen(session, quiet, seen)
                shown.append(f"=== {script}: the replay begins\n{screen}")
                for number, key in enumerate(presses, 1):
                    tmux("send-keys", "-t", session, key)
                    changed_screen(session, screen)
                    screen = settled_screen(session, quiet, seen)
                    shown.append(f"=== {script}: press {number}, {key}\n{screen}")
                    if pages is not None and number <= len(pages) and not pairs(screen, pages[number - 1]):
                        trouble = (f"at {size[0]}x{size[1]}, press {number} shows\n{screen}\nwhere the handout's "
                                   f"page {number} is\n{pages[number - 1]}")
                        break
        finally:
            ending = end_program(session)
            tmux("kill-server")
            if client is not None:
                client.wait(timeout=10)
    return seen, caption_row(screen), trouble or ending


def below_badge(screen):
    """The rows after the first (the badge's), without trailing blanks, as tmux captures them."""
    return [row.rstrip() for row in screen.rstrip("\n").split("\n")[1:]]


def same_but_verdict(shown, page, skipped, not_reached):
    """The projector's row says `skipped` where the handout's says `not_reached`, the rest the same
    (the handout's row, cut four columns sooner where the caption does not fit, begins the
    projector's)."""
    return shown.startswith(skipped) and page.startswith(not_reached) and \
        uncut(shown[len(skipped):]).startswith(uncut(page[len(not_reached):]))


def pairs(screen, page):
    """Every row below the badge's the same, but past a goal the class skipped, where the handout's
    headless run found it not reached: the message line ("GOAL skipped: ..." / "GOAL not reached:
    ...", the same quantities, in a few words where the whole does not fit) and the caption row
    ("(skipped) ..." / "(not reached) ...")."""
    shown_rows, page_rows = below_badge(screen), below_badge(page)
    if len(shown_rows) != len(page_rows):
        return False
    differing = [(shown, printed) for shown, printed in zip(shown_rows, page_rows) if shown != printed]
    if not differing:
        return True
    return len(differing) == 2 and all(
        (shown.startswith(" GOAL skipped: ") and printed.startswith(" GOAL not reached: ")) or
        same_but_verdict(shown, printed, " " + SKIPPED, " (not reached) ") for shown, printed in differing)


def handout_pages(apcs, folder, script, options, glyphs):
    """The .txt pages of the script's handout (apcs --handout, headless, on a fresh copy), in order."""
    with tempfile.TemporaryDirectory() as work:
        shutil.copytree(folder, work, dirs_exist_ok=True)
        handout = os.path.join(work, "handout-pages")
        subprocess.run([apcs, "--keys", script, "--glyphs", glyphs, "--handout", handout, *options], cwd=work,
                       stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)
        names = sorted(name for name in os.listdir(handout) if name.endswith(".txt")) if os.path.isdir(handout) else []
        return [open(os.path.join(handout, name), encoding="utf-8").read() for name in names]


def hold(apcs, data, glyphs, number, words):
    """One line of the plan played: its script, presses, captions, goals, minutes and what was seen."""
    local.socket = f"{SOCKET}-{number}"
    script, options, presses = parse(words)
    folder = script_folder(data, script)
    captions = captions_of(os.path.join(folder, script))
    goals = goals_of(os.path.join(folder, script))
    minutes = MINUTES_A_CAPTION * len(captions) + MINUTES_A_GOAL * goals + \
        animation_seconds(apcs, folder, script, options) / 60
    shown = []
    seen, last_row, trouble = play(apcs, folder, script, options, presses, glyphs, shown)
    if trouble is None:
        # Every page pairs with its PgDn, an exercise's task with the goal's feedback on the message
        # line; past the goal, the class's skip against the handout's "not reached" (pairs).
        paired = len(captions)
        pages = handout_pages(apcs, folder, script, options, glyphs)
        if len(pages) != paired:
            trouble = f"its handout has {len(pages)} pages for {len(captions)} captions"
        else:
            _, _, trouble = play(apcs, folder, script, options, presses[:paired], glyphs, [], (80, 24), pages)
    return script, presses, captions, minutes, shown, seen, last_row, trouble


def main():
    apcs, manual, data = sys.argv[1:4]
    glyphs = sys.argv[4] if len(sys.argv) > 4 else "ascii"
    screens_folder = sys.argv[5] if len(sys.argv) > 5 else None
    total_page_downs, failures = 0, []
    lines = plan_lines(manual)
    if not lines:
        sys.exit("class_plan: manual section 25 has no PRESS line")
    commands, figures, hands_on = fixed_minutes(manual)
    total_minutes = MINUTES_A_COMMAND * commands + MINUTES_A_FIGURE * figures + hands_on
    print(f"typed: {commands} commands, {figures} figures shown, {hands_on} minutes hands-on: "
          f"{total_minutes:.1f} minutes")
    # The longest plays (most presses, each waiting the longest quiet) start first.
    def waits(number):
        _, options, presses = parse(lines[number])
        return len(presses) * quiet_seconds(options)
    order = sorted(range(len(lines)), key=waits, reverse=True)
    with concurrent.futures.ThreadPoolExecutor(PLAYS_AT_ONCE) as plays:
        held = {number: plays.submit(hold, apcs, data, glyphs, number, lines[number]) for number in order}
        results = [held[number].result() for number in range(len(lines))]
    for script, presses, captions, minutes, shown, seen, last_row, trouble in results:
        if screens_folder:
            os.makedirs(screens_folder, exist_ok=True)
            with open(os.path.join(screens_folder, script + ".txt"), "w", encoding="utf-8") as out:
                out.write("\n".join(shown))
        unseen = [caption for caption in captions if not any(shown_as(caption, row) for row in seen)]
        print(f"{script}: {len(presses)} presses, {len(captions)} captions, {minutes:.1f} minutes; "
              f"last caption row: {last_row}")
        if unseen:
            failures.append(f"{script}: captions never shown with those presses: {unseen}; "
                            f"the caption rows seen: {sorted(seen)}")
        if not last_row.startswith(END_OF_SCRIPT):
            failures.append(f"{script}: the presses end at '{last_row}', not at the end of the script")
        if trouble:
            failures.append(f"{script}: {trouble}")
        total_page_downs += presses.count(TMUX_KEYS["PgDn"])
        total_minutes += minutes
    print(f"the plan: {total_page_downs} PgDn presses, {total_minutes:.1f} minutes")
    if total_page_downs > MOST_PAGE_DOWNS:
        failures.append(f"{total_page_downs} PgDn presses; expected at most {MOST_PAGE_DOWNS}")
    if total_minutes > MOST_MINUTES:
        failures.append(f"{total_minutes:.1f} minutes; expected at most {MOST_MINUTES}")
    for failure in failures:
        print("FAILED: " + failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
