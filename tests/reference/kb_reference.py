#!/usr/bin/env python3
"""Reference table for the KB spline, the acceleration law and surface fitting, computed
independently of the C++ code.

Parameters (also written into the output's header):
  the first graphic point's path: control points P0..P4 with their own t, c, b (and a per span);
  the last graphic point's path: LAST_POINTS; end slopes S0 = 0.6, S1 = 0.9 for both,
  8 samples per segment, M = 7 in-betweens by the nearest-sample rule of SPEC 4.3;
  two key frames KEY1, KEY2 of 5 points (open), whose first and last points are the paths' ends.
Formulas: thesis Eq. 3.1.4 for DS/DD, the Hermite blending functions of Ch. 2.1, and the
surface-fitting blend of SPEC 5.3 (linear along each point's progress, F1/F2 across the graphic).
Run:  python3 tests/reference/kb_reference.py > tests/reference/kb_reference.txt
"""
import math

POINTS = [  # x, y, z, t, c, b, a
    (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5),
    (2.0, 3.0, 1.0, 0.3, -0.2, 0.1, 0.5),
    (5.0, 1.0, -1.0, -0.4, 0.5, -0.6, -0.25),
    (7.5, 4.0, 2.0, 0.9, -1.0, 1.0, -0.25),
    (10.0, 2.0, 0.5, 0.0, 0.0, 0.0, 0.0),
]
LAST_POINTS = [
    (0.0, 6.0, 1.0, 0.0, 0.0, 0.0, -0.5),
    (4.0, 9.0, 3.0, 0.5, 0.2, -0.3, -0.5),
    (9.0, 7.0, 2.0, 0.0, 0.0, 0.0, 0.0),
]
KEY1 = [(0.0, 0.0, 0.0), (0.0, 1.5, 2.0), (0.5, 3.0, 0.0), (0.0, 4.0, 1.5), (0.0, 6.0, 1.0)]
KEY2 = [(10.0, 2.0, 0.5), (9.0, 3.0, 0.5), (10.0, 4.5, 1.0), (9.5, 6.0, 1.0), (9.0, 7.0, 2.0)]
SLOPES = (0.6, 0.9)
SAMPLES = 8
INBETWEENS = 7


def sub(p, q): return tuple(a - b for a, b in zip(p, q))
def add(p, q): return tuple(a + b for a, b in zip(p, q))
def mul(p, s): return tuple(a * s for a in p)
def lerp(p, q, w): return add(p, mul(sub(q, p), w))
def f1(u): return 2 * u**3 - 3 * u**2 + 1
def f2(u): return -2 * u**3 + 3 * u**2


def tangents(points, k):
    p_prev, p, p_next = (points[k - 1][:3], points[k][:3], points[k + 1][:3])
    t, c, b = points[k][3:6]
    d_in, d_out = sub(p, p_prev), sub(p_next, p)
    ds = mul(add(mul(d_in, (1 - t) * (1 - c) * (1 + b)), mul(d_out, (1 - t) * (1 + c) * (1 - b))), 0.5)
    dd = mul(add(mul(d_in, (1 - t) * (1 + c) * (1 + b)), mul(d_out, (1 - t) * (1 - c) * (1 - b))), 0.5)
    return ds, dd


def curve(points):
    n = len(points) - 1
    samples = [points[0][:3]]
    for k in range(n):
        p0, p1 = points[k][:3], points[k + 1][:3]
        t0 = mul(sub(p1, p0), SLOPES[0]) if k == 0 else tangents(points, k)[1]
        t1 = mul(sub(p1, p0), SLOPES[1]) if k + 1 == n else tangents(points, k + 1)[0]
        for j in range(1, SAMPLES + 1):
            u = j / SAMPLES
            f3, f4 = u**3 - 2 * u**2 + u, u**3 - u**2
            point = p1 if j == SAMPLES else add(add(mul(p0, f1(u)), mul(p1, f2(u))), add(mul(t0, f3), mul(t1, f4)))
            samples.append(point)
    return samples


def inbetweens(points, samples):
    """The shown in-betweens and the chord fraction each reaches."""
    chord = [0.0]
    for i in range(1, len(samples)):
        chord.append(chord[-1] + math.dist(samples[i - 1], samples[i]))
    # Spans of equal a: boundaries where a changes (the last point's a is unused).
    bounds = [0] + [k for k in range(1, len(points) - 1) if points[k][6] != points[k - 1][6]] + [len(points) - 1]
    spans = list(zip(bounds, bounds[1:]))
    lengths = [chord[e * SAMPLES] - chord[s * SAMPLES] for s, e in spans]
    quotas = [INBETWEENS * length / sum(lengths) for length in lengths]
    shares = [math.floor(q) for q in quotas]
    order = sorted(range(len(spans)), key=lambda i: -(quotas[i] - shares[i]))
    for i in order[: INBETWEENS - sum(shares)]:
        shares[i] += 1
    shown = []
    for (s, _), length, count in zip(spans, lengths, shares):
        a = points[s][6]
        for j in range(1, count + 1):
            tau = j / (count + 1)
            warp = math.sin(math.pi * tau / 2) if a < 0 else 1 - math.cos(math.pi * tau / 2)
            target = chord[s * SAMPLES] + length * ((1 - abs(a)) * tau + abs(a) * warp)
            best = min(range(len(chord)), key=lambda i: (abs(chord[i] - target), i))
            shown.append((samples[best], chord[best] / chord[-1]))
    return shown


def edge(points, key1_point, key2_point):
    """Positions and progress of one edge path in frames 0 .. M+1."""
    shown = inbetweens(points, curve(points))
    return [key1_point] + [p for p, _ in shown] + [key2_point], [0.0] + [w for _, w in shown] + [1.0]


def place_along(key):
    chord = [0.0]
    for i in range(1, len(key)):
        chord.append(chord[-1] + math.dist(key[i - 1], key[i]))
    return [c / chord[-1] for c in chord]


def surface_frames():
    e0, w0 = edge(POINTS, KEY1[0], KEY2[0])
    e1, w1 = edge(LAST_POINTS, KEY1[-1], KEY2[-1])
    v = [(a + b) / 2 for a, b in zip(place_along(KEY1), place_along(KEY2))]
    frames = []
    for k in range(len(e0)):
        d0 = sub(e0[k], lerp(KEY1[0], KEY2[0], w0[k]))
        d1 = sub(e1[k], lerp(KEY1[-1], KEY2[-1], w1[k]))
        frame = []
        for i in range(len(KEY1)):
            w = f1(v[i]) * w0[k] + f2(v[i]) * w1[k]
            frame.append(add(lerp(KEY1[i], KEY2[i], w), add(mul(d0, f1(v[i])), mul(d1, f2(v[i])))))
        frames.append(frame)
    return frames


def row(values): return " ".join(repr(v) for v in values)


def main():
    samples = curve(POINTS)
    print(f"; KB reference: slopes {SLOPES[0]} {SLOPES[1]}, {SAMPLES} samples per segment, {INBETWEENS} in-betweens")
    print("; control points: x y z t c b a")
    for p in POINTS:
        print("; " + row(p))
    print("# curve")
    for p in samples:
        print(row(p))
    print("# inbetweens")
    for p, _ in inbetweens(POINTS, samples):
        print(row(p))
    print("# last path: x y z t c b a")
    for p in LAST_POINTS:
        print(row(p))
    for name, key in (("key1", KEY1), ("key2", KEY2)):
        print(f"# {name}")
        for p in key:
            print(row(p))
    for k, frame in enumerate(surface_frames()):
        print(f"# frame {k}")
        for p in frame:
            print(row(p))


if __name__ == "__main__":
    main()
