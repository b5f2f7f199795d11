#!/usr/bin/env python3
"""In-between frames of a session computed from its files independently of the C++ code, and held
against in-between files the program wrote or that were approved (tests/golden).

The model: SPEC 2.1 (.dat text), 5.1 (adding points by Algorithm 2; one open part a key, which is
what the examples have), 4.2-4.3 (each edge path's KB curve, 32 samples a segment, and its
nearest-sample in-betweens, from kb_reference.py) and 5.3 (the blend across the graphic).

Usage: fit_model.py KEY1 KEY2 FIRST_PATH LAST_PATH --inbetweens M [--first-slopes S0 S1]
                    [--last-slopes S0 S1] K:INB_FILE...
  FIRST_PATH, LAST_PATH: the path files of the first and last graphic point as the session wrote
  them (their t c b a columns, and SLOPES if they have it; the slope options override it);
  K:INB_FILE: in-between file K of M.
Exits 1, naming file, point and coordinate, when a file's part or point count differs or a number
is more than 1e-7 off (in-between files keep 8 decimals).
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kb_reference as kb  # noqa: E402

TOLERANCE = 1e-7


def read_dat(name):
    """Parts [(name, closure, points)] and the SLOPES of a .dat file; points of 3 or 7 numbers."""
    parts, slopes, first_data = [], (1.0, 1.0), True
    with open(name, encoding="utf-8-sig") as text:
        for line in text:
            words = line.split(";")[0].split("#")[0].replace("\x1a", "").split()
            if not words:
                continue
            if words[0].upper() == "PART":
                parts.append((words[1], words[2].upper() if len(words) > 2 else "OPEN", []))
            elif words[0].upper() == "SLOPES":
                slopes = (float(words[1]), float(words[2]))
            elif first_data and len(words) == 1:
                pass  # the optional point count
            else:
                if not parts:
                    parts.append(("", "OPEN", []))
                numbers = [float(w) for w in words]
                if len(numbers) == 2:
                    numbers.append(0.0)
                if len(numbers) == 3:
                    numbers += [0.0, 0.0, 0.0, 0.0]
                parts[-1][2].append(tuple(numbers))
            first_data = False
    return parts, slopes


def added_points(points, more):
    """Algorithm 2 on the smaller graphic: RT = (segments + more) div segments, RS = (segments +
    more) mod segments, i.e. (NP1 - 1) div and mod (NP2 - 1); the first RS segments get RT new
    points each, the others RT - 1, evenly along the segment."""
    segments = len(points) - 1
    rt, rs = (len(points) - 1 + more) // segments, (len(points) - 1 + more) % segments
    result = [points[0]]
    for s in range(segments):
        count = rt if s < rs else rt - 1
        for j in range(1, count + 1):
            result.append(kb.lerp(points[s], points[s + 1], j / (count + 1)))
        result.append(points[s + 1])
    return result


def equalised(key1, key2):
    if len(key1) != 1 or len(key2) != 1 or key1[0][1] != "OPEN" or key2[0][1] != "OPEN":
        sys.exit("fit_model.py: the model covers keys of one open part")
    first = [p[:3] for p in key1[0][2]]
    second = [p[:3] for p in key2[0][2]]
    if len(first) > len(second):
        second = added_points(second, len(first) - len(second))
    elif len(second) > len(first):
        first = added_points(first, len(second) - len(first))
    return first, second


def edge(path_file, key1_point, key2_point, count, slopes_given):
    parts, slopes = read_dat(path_file)
    slopes = tuple(slopes_given) if slopes_given else slopes
    points = [p for part in parts for p in part[2]]
    if sum(kb.math.dist(p[:3], q[:3]) for p, q in zip(points, points[1:])) == 0:
        sys.exit(f"fit_model.py: {path_file}: the model covers paths of some length")
    return kb.edge(points, key1_point, key2_point, slopes, 32, count)


def main():
    arguments = argparse.ArgumentParser()
    for name in ("key1", "key2", "first_path", "last_path"):
        arguments.add_argument(name)
    arguments.add_argument("--inbetweens", type=int, required=True)
    for name in ("--first-slopes", "--last-slopes"):
        arguments.add_argument(name, type=float, nargs=2, metavar=("S0", "S1"),
                               help="the end slopes the path was shaped with (default: its SLOPES, else 1 1)")
    arguments.add_argument("files", nargs="+", metavar="K:INB_FILE")
    given = arguments.parse_args()
    key1_parts, _ = read_dat(given.key1)
    key1, key2 = equalised(key1_parts, read_dat(given.key2)[0])
    frames = kb.blend(key1, key2, edge(given.first_path, key1[0], key2[0], given.inbetweens, given.first_slopes),
                      edge(given.last_path, key1[-1], key2[-1], given.inbetweens, given.last_slopes))
    largest, failed = 0.0, False
    for item in given.files:
        k, name = item.split(":", 1)
        parts, _ = read_dat(name)
        points = [p[:3] for part in parts for p in part[2]]
        expected = frames[int(k)]
        if [(n, c) for n, c, _ in parts] != [(n, c) for n, c, _ in key1_parts] or len(points) != len(expected):
            print(f"{name}: parts {[(n, c, len(p)) for n, c, p in parts]}, expected {len(expected)} points "
                  f"in the parts of {given.key1}")
            failed = True
            continue
        for i, (point, model) in enumerate(zip(points, expected)):
            for axis, (value, wanted) in enumerate(zip(point, model)):
                largest = max(largest, abs(value - wanted))
                if abs(value - wanted) > TOLERANCE:
                    print(f"{name}: point {i + 1} {'xyz'[axis]} is {value!r}, the model says {wanted!r}")
                    failed = True
    print(f"{len(given.files)} in-between files, largest difference from the model {largest:.2e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
