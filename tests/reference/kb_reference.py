#!/usr/bin/env python3
"""Reference table for the KB spline and the acceleration law, computed independently of the C++ code.

Parameters (also written into the output's header):
  control points P0..P4 with their own t, c, b (and a per span), end slopes S0 = 0.6, S1 = 0.9,
  8 samples per segment, M = 7 in-betweens by the nearest-sample rule of SPEC 4.3.
Formulas: thesis Eq. 3.1.4 for DS/DD, the Hermite blending functions of Ch. 2.1.
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
SLOPES = (0.6, 0.9)
SAMPLES = 8
INBETWEENS = 7


def sub(p, q): return tuple(a - b for a, b in zip(p, q))
def add(p, q): return tuple(a + b for a, b in zip(p, q))
def mul(p, s): return tuple(a * s for a in p)


def tangents(k):
    p_prev, p, p_next = (POINTS[k - 1][:3], POINTS[k][:3], POINTS[k + 1][:3])
    t, c, b = POINTS[k][3:6]
    d_in, d_out = sub(p, p_prev), sub(p_next, p)
    ds = mul(add(mul(d_in, (1 - t) * (1 - c) * (1 + b)), mul(d_out, (1 - t) * (1 + c) * (1 - b))), 0.5)
    dd = mul(add(mul(d_in, (1 - t) * (1 + c) * (1 + b)), mul(d_out, (1 - t) * (1 - c) * (1 - b))), 0.5)
    return ds, dd


def curve():
    n = len(POINTS) - 1
    samples = [POINTS[0][:3]]
    for k in range(n):
        p0, p1 = POINTS[k][:3], POINTS[k + 1][:3]
        t0 = mul(sub(p1, p0), SLOPES[0]) if k == 0 else tangents(k)[1]
        t1 = mul(sub(p1, p0), SLOPES[1]) if k + 1 == n else tangents(k + 1)[0]
        for j in range(1, SAMPLES + 1):
            u = j / SAMPLES
            f1, f2 = 2 * u**3 - 3 * u**2 + 1, -2 * u**3 + 3 * u**2
            f3, f4 = u**3 - 2 * u**2 + u, u**3 - u**2
            point = p1 if j == SAMPLES else add(add(mul(p0, f1), mul(p1, f2)), add(mul(t0, f3), mul(t1, f4)))
            samples.append(point)
    return samples


def inbetweens(samples):
    chord = [0.0]
    for i in range(1, len(samples)):
        chord.append(chord[-1] + math.dist(samples[i - 1], samples[i]))
    # Spans of equal a: boundaries where a changes (the last point's a is unused).
    bounds = [0] + [k for k in range(1, len(POINTS) - 1) if POINTS[k][6] != POINTS[k - 1][6]] + [len(POINTS) - 1]
    spans = list(zip(bounds, bounds[1:]))
    lengths = [chord[e * SAMPLES] - chord[s * SAMPLES] for s, e in spans]
    quotas = [INBETWEENS * length / sum(lengths) for length in lengths]
    shares = [math.floor(q) for q in quotas]
    order = sorted(range(len(spans)), key=lambda i: -(quotas[i] - shares[i]))
    for i in order[: INBETWEENS - sum(shares)]:
        shares[i] += 1
    shown = []
    for (s, _), length, count in zip(spans, lengths, shares):
        a = POINTS[s][6]
        for j in range(1, count + 1):
            tau = j / (count + 1)
            warp = math.sin(math.pi * tau / 2) if a < 0 else 1 - math.cos(math.pi * tau / 2)
            target = chord[s * SAMPLES] + length * ((1 - abs(a)) * tau + abs(a) * warp)
            best = min(range(len(chord)), key=lambda i: (abs(chord[i] - target), i))
            shown.append(samples[best])
    return shown


def main():
    samples = curve()
    print(f"; KB reference: slopes {SLOPES[0]} {SLOPES[1]}, {SAMPLES} samples per segment, {INBETWEENS} in-betweens")
    print("; control points: x y z t c b a")
    for p in POINTS:
        print("; " + " ".join(repr(v) for v in p))
    print("# curve")
    for p in samples:
        print(" ".join(repr(v) for v in p))
    print("# inbetweens")
    for p in inbetweens(samples):
        print(" ".join(repr(v) for v in p))


if __name__ == "__main__":
    main()
