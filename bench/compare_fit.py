#!/usr/bin/python3
"""apcs fit against its numpy peer on 10^5-point keys with 12 in-betweens.

  bench/compare_fit.py build/release/apcs [--points 100000] [--rounds 5]

Writes the inputs to a temporary folder, runs both whole processes alternately, checks that every
in-between agrees to 1e-5, and prints wall times, their ratio and peak memory (max RSS of each
process, from /usr/bin/time) beside the in-memory size of the frames.
"""
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def write_inputs(folder, points):
    t = np.arange(points) / points
    key1 = np.column_stack([np.zeros(points), 10 * t, np.sin(20 * t)])
    key2 = np.column_stack([np.full(points, 8.0), 10 * t, np.sin(20 * t + 1.5)])
    np.savetxt(f"{folder}/key1.dat", key1, fmt="%.17g")
    np.savetxt(f"{folder}/key2.dat", key2, fmt="%.17g")
    for name, a, b in (("first.dat", key1[0], key2[0]), ("last.dat", key1[-1], key2[-1])):
        middle = (a + b) / 2 + np.array([2.0, 1.0, 3.0])
        with open(f"{folder}/{name}", "w") as f:
            f.write("%r %r %r\n" % tuple(a))
            f.write("%r %r %r 0.2 0 0 0.3\n" % tuple(middle))
            f.write("%r %r %r\n" % tuple(b))


def run(command):
    """Wall time and peak RSS of a whole process. The peak comes from /usr/bin/time, a small
    parent: Linux keeps a process's peak across exec, so a child forked from this Python (numpy
    loaded, 40 MiB) would report the interpreter's size instead of its own."""
    with tempfile.NamedTemporaryFile() as peak:
        start = time.perf_counter()
        status = subprocess.call(["/usr/bin/time", "-f", "%M", "-o", peak.name, *command], stdout=subprocess.DEVNULL)
        elapsed = time.perf_counter() - start
        if status != 0:
            sys.exit(f"failed: {' '.join(command)}")
        return elapsed, int(open(peak.name).read().split()[-1]) * 1024


def frames(folder, count):
    return [np.loadtxt(f"{folder}/inb{k:03d}.dat", comments=[";", "PART"]) for k in range(1, count + 1)]


def main():
    apcs = sys.argv[1]
    points = int(sys.argv[sys.argv.index("--points") + 1]) if "--points" in sys.argv else 100000
    rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 5
    with tempfile.TemporaryDirectory() as folder:
        write_inputs(folder, points)
        os.makedirs(f"{folder}/apcs")
        os.makedirs(f"{folder}/peer")
        inputs = [f"{folder}/key1.dat", f"{folder}/key2.dat", f"{folder}/first.dat", f"{folder}/last.dat"]
        ours, theirs = [], []
        for _ in range(rounds):
            # Every round writes new files: an unchanged file is only compared by apcs, which
            # would make its rounds after the first cheaper than the peer's.
            for name in os.listdir(f"{folder}/apcs"):
                os.remove(f"{folder}/apcs/{name}")
            ours.append(run([apcs, "fit", *inputs, "--inbetweens", "12", "--out", f"{folder}/apcs"]))
            theirs.append(run([sys.executable, f"{HERE}/peer_fit_numpy.py", *inputs, f"{folder}/peer",
                               "--inbetweens", "12"]))
        worst = max(float(np.max(np.abs(a - b))) for a, b in zip(frames(f"{folder}/apcs", 12), frames(f"{folder}/peer", 12)))
        ours_time = sorted(t for t, _ in ours)[rounds // 2]
        theirs_time = sorted(t for t, _ in theirs)[rounds // 2]
        frames_bytes = points * 14 * 3 * 8
        _, baseline = run([apcs, "--version"])
        print(f"points {points}, 12 in-betweens, {rounds} rounds each, alternating")
        print(f"apcs fit   median {ours_time * 1000:8.1f} ms   peak RSS {max(m for _, m in ours) / 2**20:7.1f} MiB")
        print(f"numpy peer median {theirs_time * 1000:8.1f} ms   peak RSS {max(m for _, m in theirs) / 2**20:7.1f} MiB")
        print(f"speed-up {theirs_time / ours_time:.1f}x; all frames in memory would be {frames_bytes / 2**20:.1f} MiB, "
              f"the keys and two frames {points * 4 * 3 * 8 / 2**20:.1f} MiB; apcs --version alone peaks at "
              f"{baseline / 2**20:.1f} MiB; largest difference between the frames {worst:.2e}")
        if worst > 1e-5:
            sys.exit("the frames differ by more than 1e-5")


if __name__ == "__main__":
    main()
