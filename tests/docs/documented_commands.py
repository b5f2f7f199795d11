#!/usr/bin/env python3
"""Every `apcs …` command line the docs show runs as written.

The lines come from README.md's code blocks, manual.txt's indented examples, the man page's
.nf/.fi blocks and each command's --help examples. Each runs with no terminal in a fresh scratch
folder holding a copy of data/ and work/ (a copy of data/n-to-l, as the docs' "cp -r … work"
makes it): in the example folder whose files it names (n-to-l when it names none), or in the
scratch folder when it names data/, work or an example's folder. The lines before it in the same
block (a "$ printf … > ani1.dat", the apcs fit whose files an apcs draw overlays) run first. A
line the docs follow with an "apcs: …" message must fail with that message; any other must exit
0. Lines with a placeholder in capitals (FILE, DIR, SCENE.scn …), synopses ([options], a|b) and
the interactive ones (the session without --keys, --pace, apcs play without an output) are not
run, but counted, and every option they name must be one their command takes.

Usage: documented_commands.py APCS SOURCE_TREE   (prints a line per command, then the counts)
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

EXAMPLES = ("n-to-l", "stick", "snake-apple", "robot", "bicycle", "car")
COMMANDS = ("path", "inbetween", "fit", "draw", "play", "figures", "grade")
OUTPUTS = ("--print", "--out", "--png", "--png-raw", "--svg", "--gif", "--sixel", "--kitty", "--tree")


class Line:
    def __init__(self, where, text, message, before=()):
        self.where, self.text, self.message, self.before = where, text, message, list(before)


def command_part(text):
    """The command of a doc line: '$ ' dropped, a description after two spaces cut off."""
    text = text.strip()
    if text.startswith("$ "):
        text = text[2:]
    return re.split(r"\s{2,}", text)[0].strip()


def following_message(lines, index):
    for later in lines[index + 1:index + 3]:
        stripped = later.strip()
        if stripped.startswith("apcs: "):
            return stripped[len("apcs: "):]
        if stripped:
            return None
    return None


def shell_line(text):
    """A command of a block that sets up for the next: "$ printf …", an earlier apcs line."""
    command = command_part(text)
    return command if text.strip().startswith("$ ") or command.split(" ")[0] == "apcs" else None


def from_readme(path):
    lines = open(path).read().split("\n")
    inside, before = False, []
    for index, line in enumerate(lines):
        if line.strip().startswith("```"):
            inside, before = not inside, []
            continue
        if inside and command_part(line).startswith("apcs"):
            yield Line(f"README.md:{index + 1}", command_part(line), following_message(lines, index), before)
        if inside and shell_line(line):
            before.append(shell_line(line))


def indent(line):
    return len(line) - len(line.lstrip())


def from_manual(path):
    lines = open(path).read().split("\n")
    before = []
    for index, line in enumerate(lines):
        if not line.startswith("  "):
            before = []
            continue
        text = command_part(line)
        # A command wrapped onto a line indented a little deeper (not a description column).
        if text == line.strip() and index + 1 < len(lines) and indent(line) < indent(lines[index + 1]) < 16:
            text += " " + lines[index + 1].strip()
        if text.split(" ")[0] == "apcs":
            yield Line(f"manual.txt:{index + 1}", text, following_message(lines, index), before)
        if shell_line(line):
            before.append(text if text.split(" ")[0] == "apcs" else shell_line(line))


def from_man_page(path):
    lines = open(path).read().split("\n")
    inside, before = False, []
    for index, line in enumerate(lines):
        text = line.replace("\\-", "-").replace("\\&", "")
        if line.startswith(".nf"):
            inside, before = True, []
        elif line.startswith(".fi"):
            inside = False
        elif inside and line.startswith("apcs"):
            yield Line(f"man/apcs.1:{index + 1}", text, None, before)
            before.append(text)


def from_help(apcs):
    for command in ("",) + COMMANDS:
        text = subprocess.run([apcs, *command.split(), "--help"], capture_output=True, text=True).stdout
        for line in text.split("\n"):
            if line.startswith("  apcs"):
                yield Line(f"apcs {command} --help".replace("  ", " "), command_part(line), None)


PLACEHOLDER = re.compile(r"(^|[\s=/\[])([A-Z][A-Z0-9_]+)(\.[a-z]+)?($|[\s\]|.])")


def placeholder_of(text):
    if "[" in text or "..." in text or "…" in text or re.search(r"\w\|\w", text.replace(" | ", " ")):
        return "a synopsis"
    for word in shlex.split(text, posix=True) if text.count("'") % 2 == 0 else text.split():
        if re.fullmatch(r"[A-Z][A-Z0-9_]*(\.[a-z]+)?", word) and word not in ("Y", "N"):
            return word
    return None


def words_of(text):
    return shlex.split(text)


def command_of(words):
    return next((word for word in words[1:] if word in COMMANDS), None)


def interactive(words):
    command = command_of(words)
    if "--pace" in words:
        return True
    if command is None:
        return "--keys" not in words and "--help" not in words and "--version" not in words
    return "--pace" in words or command == "play" and not any(option in words for option in OUTPUTS)


def options_taken(apcs, command, cache={}):
    if command not in cache:
        help_text = subprocess.run([apcs, *([command] if command else []), "--help"], capture_output=True,
                                   text=True).stdout
        cache[command] = set(re.findall(r"--[a-z][a-z-]*", help_text))
    return cache[command]


def unknown_options(apcs, words):
    command = command_of(words)
    named = [word.split("=")[0] for word in words if word.startswith("--")]
    return [option for option in named if option not in options_taken(apcs, command)
            and option not in options_taken(apcs, None)]


def folder_for(text, data):
    if re.search(r"(^|[\s=])(data|work)(/|\s|$)", text):
        return os.path.dirname(data)
    if any(f"{example}/" in text for example in EXAMPLES) and "../" not in text:
        return data
    names = re.findall(r"[\w.-]+\.(?:dat|scn|keys)\b", text)
    for example in EXAMPLES:
        if all(os.path.exists(os.path.join(data, example, name)) for name in names):
            return os.path.join(data, example)
    return os.path.join(data, "n-to-l")


def run(apcs, source_tree, line):
    scratch = tempfile.mkdtemp(prefix="apcs-docs-")
    try:
        data = os.path.join(scratch, "data")
        shutil.copytree(os.path.join(source_tree, "data"), data)
        shutil.copytree(os.path.join(data, "n-to-l"), os.path.join(scratch, "work"))
        folder = folder_for(" ".join([*line.before, line.text]), data)
        binary = os.path.dirname(os.path.abspath(apcs))
        environment = dict(os.environ, PATH=binary + os.pathsep + os.environ["PATH"], APCS_DATA=data)
        for earlier in line.before:
            subprocess.run(["bash", "-c", earlier], cwd=folder, env=environment, capture_output=True,
                           stdin=subprocess.DEVNULL, timeout=120)
        return subprocess.run(["bash", "-c", line.text], cwd=folder, env=environment, capture_output=True,
                              text=True, stdin=subprocess.DEVNULL, timeout=120)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def check(apcs, source_tree, line):
    """None when the line is as documented, else what is wrong; 'skipped: …' for a line not run."""
    try:
        words = words_of(line.text)
    except ValueError:
        return "cannot be split into words"
    unknown = unknown_options(apcs, words)
    if unknown and line.message is None:
        return "names options its command does not take: " + " ".join(unknown)
    if placeholder := placeholder_of(line.text):
        return f"skipped: {placeholder}"
    if interactive(words):
        return "skipped: interactive"
    result = run(apcs, source_tree, line)
    if line.message is None:
        if result.returncode != 0:
            return f"exit {result.returncode}: {result.stderr.strip()[:300]}"
        return None
    said = result.stderr.split("\n")[0].removeprefix("apcs: ")
    known = re.split(r"\.\.\.|…|[A-Z]{3,}", line.message)[0].strip()
    if result.returncode == 0 or not said.startswith(known):
        return f"expected to fail with 'apcs: {line.message}', got exit {result.returncode}: {said}"
    return None


def is_command(text):
    """Not prose that starts with the word apcs ("apcs with a lower --inbetweens")."""
    words = text.split()
    return len(words) == 1 or words[1].startswith("-") or words[1] in COMMANDS or words[1] in ("[options]",)


def main():
    apcs, source_tree = os.path.abspath(sys.argv[1]), sys.argv[2]
    sources = {"README.md": list(from_readme(os.path.join(source_tree, "README.md"))),
               "manual.txt": list(from_manual(os.path.join(source_tree, "manual.txt"))),
               "man/apcs.1": list(from_man_page(os.path.join(source_tree, "man", "apcs.1"))),
               "apcs --help": list(from_help(apcs))}
    lines = [line for found in sources.values() for line in found]
    counts = {"ran": 0, "skipped": 0, "failed": 0}
    ran_from = {source: 0 for source in sources}
    for line in filter(lambda line: is_command(line.text), lines):
        problem = check(apcs, source_tree, line)
        if problem is None:
            counts["ran"] += 1
            for source, found in sources.items():
                ran_from[source] += any(line is other for other in found)
            print(f"ok       {line.where}: {line.text}")
        elif problem.startswith("skipped"):
            counts["skipped"] += 1
            print(f"{problem[:8]} {line.where}: {line.text}  ({problem[9:]})")
        else:
            counts["failed"] += 1
            print(f"FAILED   {line.where}: {line.text}\n         {problem}")
    print(f"{counts['ran']} documented command lines ran as documented, {counts['skipped']} skipped, "
          f"{counts['failed']} failed")
    # A source that gave no command that ran would pass on nothing checked (its reader found none).
    unchecked = [source for source, ran in ran_from.items() if ran == 0]
    for source in unchecked:
        print(f"FAILED   {source}: no documented command line ran from it; its reader found none")
    sys.exit(1 if counts["failed"] or unchecked else 0)


if __name__ == "__main__":
    main()
