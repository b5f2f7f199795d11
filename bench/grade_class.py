#!/usr/bin/env python3
"""apcs grade on a class's worth of recordings, as a teacher runs it (SPEC §3.2; issue 57):
200 recordings of exercise 1 — right, wrong, another exercise's, empty, binary, 10 MB, 100,000
keys, the slow one (16,000 inserted points, then staff keys), names with commas, quotes, line ends,
a formula and bytes that are not UTF-8 — then a class folder of 40 students x 5 exercises
(apcs grade --class --feedback). Prints the wall time and the peak memory of each run (the
process's maximum resident set, from getrusage) and checks that Python's csv module reads the
output back at its defaults, a row per goal or student.

Usage: bench/grade_class.py build/release/apcs [RUNS]
Targets (SPEC §3.2): under 5 s on 2 cores, under 100 MB. A benchmark, not a test: figures go to
docs/PERFORMANCE.md."""

import csv
import io
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
EXERCISES = os.path.join(ROOT, "data", "exercises")
NAMES = ["1-tension", "2-continuity", "3-bias", "4-near", "5-inbetween"]


def exercise_text(name):
    with open(os.path.join(EXERCISES, f"exercise-{name}.keys"), encoding="utf-8") as file:
        return file.read()


def answer_text(name):
    with open(os.path.join(EXERCISES, "answers", f"exercise-{name}-answer.keys"), encoding="utf-8") as file:
        return file.read()


def staff_keys(count):
    return "".join("6\n" if key % 2 == 0 else "4\n" for key in range(count))


def recordings(folder):
    """The 200 files of exercise 1 (names as bytes: one is not UTF-8)."""
    tension = exercise_text("1-tension")
    kinds = {
        b"right": answer_text("1-tension").encode(),
        b"wrong": (tension + "6\n").encode(),
        b"other": answer_text("2-continuity").encode(),
        b"empty": b"",
        b"binary": bytes(range(256)) * 64,
        b"ten-mb": b"; padding\n" * (1 << 20),
        b"keys-100000": (tension + staff_keys(99_950) + "L L L 6\n").encode(),
        b"slow": (tension + "ENTER ENTER ENTER ENTER\nY\nW\n" + "I\n" * 16_000 + "ENTER\n8\n" +
                  staff_keys(82_000 - 16_010) + "L L L 6\n").encode(),
        b"comma, and \"quote\"": answer_text("1-tension").encode(),
        b"line\nend": answer_text("1-tension").encode(),
        b"=HYPERLINK(1)": answer_text("1-tension").encode(),
        b"not-utf8-\xff\xfe": answer_text("1-tension").encode(),
    }
    # One of each hostile kind, as a class would hand them in; the rest right and wrong in turn.
    ordinary = [b"right", b"wrong"]
    names = [name for name in kinds if name not in ordinary]
    while len(names) < 200:
        names.append(ordinary[len(names) % 2])
    files = []
    for index, name in enumerate(names):
        path = os.path.join(os.fsencode(folder), b"%03d-" % index + name + b".keys")
        with open(path, "wb") as file:
            file.write(kinds[name])
        files.append(path)
    return files


def class_folder(folder):
    """40 students, each with the five exercises: right, wrong or missing in turn."""
    for student in range(40):
        home = os.path.join(folder, f"student-{student:02d}")
        os.makedirs(home)
        for number, name in enumerate(NAMES):
            kind = (student + number) % 3
            if kind == 2:
                continue
            text = answer_text(name) if kind == 0 else exercise_text(name) + "6\n"
            with open(os.path.join(home, f"exercise-{name}.keys"), "w", encoding="utf-8") as file:
                file.write(text)


def timed(command):
    """Wall seconds, peak resident megabytes, standard output, exit status."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    start = time.monotonic()
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, check=False)
    seconds = time.monotonic() - start
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    # ru_maxrss of the children is the largest one so far: a run smaller than an earlier one
    # reads as that one (runs go largest first).
    return seconds, max(peak, before) / 1024, run.stdout, run.returncode


def main():
    apcs = os.path.abspath(sys.argv[1])
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    with tempfile.TemporaryDirectory() as work:
        for name in NAMES:
            shutil.copy(os.path.join(EXERCISES, f"exercise-{name}.keys"), work)
        for data in ("key1.dat", "key2.dat", "way1.dat"):
            shutil.copy(os.path.join(EXERCISES, data), work)
        handed_in = os.path.join(work, "in")
        os.makedirs(handed_in)
        files = recordings(handed_in)
        room = os.path.join(work, "class")
        class_folder(room)
        exercises = [os.path.join(work, f"exercise-{name}.keys") for name in NAMES]
        plain = [apcs, "grade", exercises[0]] + [os.fsdecode(file) for file in files]
        gradebook = [apcs, "grade", "--class", room, "--feedback", os.path.join(work, "returned")] + exercises
        for label, command, rows in (("200 recordings", plain, 200), ("--class 40 x 5", gradebook, 40)):
            for run in range(runs):
                seconds, megabytes, out, status = timed(command)
                table = list(csv.reader(io.StringIO(out.decode("utf-8"), newline="")))
                assert len(table) == rows + 1, f"{label}: {len(table) - 1} rows read back, not {rows}"
                print(f"{label}: run {run + 1}: {seconds:.2f} s, peak {megabytes:.1f} MB, exit {status}, "
                      f"{len(table) - 1} rows read back by csv")


if __name__ == "__main__":
    main()
