#!/usr/bin/python3
"""The peer of `apcs fit`, in numpy: the same batch job on the same inputs.

  peer_fit_numpy.py KEY1 KEY2 PATH_FIRST PATH_LAST OUT_DIR [--inbetweens M] [--samples N]

Keys of equal point count in one part (what the benchmark feeds both programs), path files of
3 or 7 columns, KB tangents (thesis Eq. 3.1.4), end slopes 1 1, nearest-sample in-betweens with
the acceleration law of SPEC 4.3, the surface blend of SPEC 5.3; writes inb001.dat ... like apcs.
"""
import math
import sys

import numpy as np


def read_dat(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split(';')[0].split('#')[0].strip()
            if not line or line.upper().startswith('PART'):
                continue
            fields = line.split()
            if len(fields) == 1:
                continue  # the count line
            rows.append([float(v) for v in fields] + [0.0] * (7 - len(fields)) if len(fields) != 2
                        else [float(fields[0]), float(fields[1]), 0.0, 0.0, 0.0, 0.0, 0.0])
    return np.array(rows, dtype=float)


def read_points(path):
    text = open(path).read()
    lines = [l.split(';')[0].split('#')[0] for l in text.splitlines()]
    data = [l for l in lines if l.strip() and not l.strip().upper().startswith('PART') and len(l.split()) > 1]
    return np.array(' '.join(data).split(), dtype=float).reshape(-1, 3)


def kb_curve(control, samples):
    p = control[:, :3]
    n = len(p) - 1
    u = np.arange(1, samples + 1) / samples
    f1, f2 = 2 * u**3 - 3 * u**2 + 1, -2 * u**3 + 3 * u**2
    f3, f4 = u**3 - 2 * u**2 + u, u**3 - u**2
    curve = [p[0:1]]
    for k in range(n):
        def tangents(j):
            t, c, b = control[j, 3:6]
            d_in, d_out = p[j] - p[j - 1], p[j + 1] - p[j]
            ds = ((1 - t) * (1 - c) * (1 + b) * d_in + (1 - t) * (1 + c) * (1 - b) * d_out) / 2
            dd = ((1 - t) * (1 + c) * (1 + b) * d_in + (1 - t) * (1 - c) * (1 - b) * d_out) / 2
            return ds, dd
        t0 = p[1] - p[0] if k == 0 else tangents(k)[1]
        t1 = p[n] - p[n - 1] if k + 1 == n else tangents(k + 1)[0]
        seg = np.outer(f1, p[k]) + np.outer(f2, p[k + 1]) + np.outer(f3, t0) + np.outer(f4, t1)
        seg[-1] = p[k + 1]
        curve.append(seg)
    return np.vstack(curve)


def inbetweens(control, curve, samples, count):
    chord = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(curve, axis=0), axis=1))])
    n = len(control) - 1
    bounds = [0] + [k for k in range(1, n) if control[k, 6] != control[k - 1, 6]] + [n]
    spans = list(zip(bounds, bounds[1:]))
    lengths = [chord[e * samples] - chord[s * samples] for s, e in spans]
    total = sum(lengths)
    quotas = [count * l / total if total > 0 else count / len(spans) for l in lengths]
    shares = [math.floor(q) for q in quotas]
    for i in sorted(range(len(spans)), key=lambda i: -(quotas[i] - shares[i]))[: count - sum(shares)]:
        shares[i] += 1
    shown, fractions = [], []
    for (s, _), length, m in zip(spans, lengths, shares):
        a = control[s, 6]
        tau = np.arange(1, m + 1) / (m + 1)
        warp = np.sin(np.pi * tau / 2) if a < 0 else 1 - np.cos(np.pi * tau / 2)
        targets = chord[s * samples] + length * ((1 - abs(a)) * tau + abs(a) * warp)
        for d in targets:
            above = int(np.searchsorted(chord, d))
            if above == 0:
                best = 0
            elif above == len(chord):
                best = len(chord) - 1
            else:
                best = above - 1 if d - chord[above - 1] <= chord[above] - d else above
            shown.append(curve[best])
            fractions.append(chord[best] / chord[-1] if chord[-1] > 0 else 0.0)
    return np.array(shown), np.array(fractions)


def parameters(key):
    chord = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(key, axis=0), axis=1))])
    return chord / chord[-1] if chord[-1] > 0 else np.linspace(0, 1, len(key))


def main():
    args = sys.argv[1:]
    count = int(args[args.index('--inbetweens') + 1]) if '--inbetweens' in args else 12
    samples = int(args[args.index('--samples') + 1]) if '--samples' in args else 32
    key1, key2 = read_points(args[0]), read_points(args[1])
    first, last = read_dat(args[2]), read_dat(args[3])
    out = args[4]
    e0, w0 = inbetweens(first, kb_curve(first, samples), samples, count)
    e1, w1 = inbetweens(last, kb_curve(last, samples), samples, count)
    v = (parameters(key1) + parameters(key2)) / 2
    g1, g2 = 2 * v**3 - 3 * v**2 + 1, -2 * v**3 + 3 * v**2
    change = key2 - key1
    # apcs' in-between format: fixed decimals, 9 - floor(log10 of the keys' largest coordinate).
    size = max(np.abs(key1).max(), np.abs(key2).max())
    decimals = max(0, 9 - int(np.floor(np.log10(size)))) if size > 0 else 9
    for k in range(count):
        # SPEC 5.3: each point's progress blends the edges' across the graphic; the edges' bends
        # off their chords are added with the same weights.
        w = g1 * w0[k] + g2 * w1[k]
        bend0 = e0[k] - (key1[0] + (key2[0] - key1[0]) * w0[k])
        bend1 = e1[k] - (key1[-1] + (key2[-1] - key1[-1]) * w1[k])
        frame = key1 + change * w[:, None] + np.outer(g1, bend0) + np.outer(g2, bend1)
        frame[0], frame[-1] = e0[k], e1[k]
        with open(f"{out}/inb{k + 1:03d}.dat", "w") as f:
            f.write(f"; APCS in-between {k + 1} of {count}\n")
            np.savetxt(f, frame, fmt=f"%.{decimals}f")


if __name__ == "__main__":
    main()
