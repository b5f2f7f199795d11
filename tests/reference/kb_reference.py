#!/usr/bin/env python3
"""Reference table for the KB spline, the acceleration law and surface fitting, computed
independently of the C++ code.

Parameters (also written into the output's header):
  the first graphic point's path: control points P0..P4 with their own t, c, b (and a per span);
  the last graphic point's path: LAST_POINTS; end slopes S0 = 0.6, S1 = 0.9 for both,
  8 samples per segment, M = 7 in-betweens by the nearest-sample rule of SPEC 4.3, and the same
  in-betweens with exact spacing (SPEC 4.4: at their arc length);
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


def curve(points, slopes=SLOPES, per_segment=SAMPLES):
    n = len(points) - 1
    samples = [points[0][:3]]
    for k in range(n):
        p0, p1 = points[k][:3], points[k + 1][:3]
        t0 = mul(sub(p1, p0), slopes[0]) if k == 0 else tangents(points, k)[1]
        t1 = mul(sub(p1, p0), slopes[1]) if k + 1 == n else tangents(points, k + 1)[0]
        for j in range(1, per_segment + 1):
            u = j / per_segment
            f3, f4 = u**3 - 2 * u**2 + u, u**3 - u**2
            point = p1 if j == per_segment else add(add(mul(p0, f1(u)), mul(p1, f2(u))), add(mul(t0, f3), mul(t1, f4)))
            samples.append(point)
    return samples


def shares_by_largest_remainder(lengths, count):
    quotas = [count * length / sum(lengths) for length in lengths]
    shares = [math.floor(q) for q in quotas]
    order = sorted(range(len(lengths)), key=lambda i: -(quotas[i] - shares[i]))
    for i in order[: count - sum(shares)]:
        shares[i] += 1
    return shares


def law(a, tau):
    """SPEC 4.3: the fraction of a span's length reached at time fraction tau with acceleration a."""
    warp = math.sin(math.pi * tau / 2) if a < 0 else 1 - math.cos(math.pi * tau / 2)
    return (1 - abs(a)) * tau + abs(a) * warp


def span_bounds(points):
    """Spans of equal a: boundaries where a changes (the last point's a is unused)."""
    bounds = [0] + [k for k in range(1, len(points) - 1) if points[k][6] != points[k - 1][6]] + [len(points) - 1]
    return list(zip(bounds, bounds[1:]))


def inbetweens(points, samples, count=INBETWEENS, per_segment=SAMPLES):
    """The shown in-betweens and the chord fraction each reaches."""
    chord = [0.0]
    for i in range(1, len(samples)):
        chord.append(chord[-1] + math.dist(samples[i - 1], samples[i]))
    spans = span_bounds(points)
    lengths = [chord[e * per_segment] - chord[s * per_segment] for s, e in spans]
    shown = []
    for (s, _), length, share in zip(spans, lengths, shares_by_largest_remainder(lengths, count)):
        for j in range(1, share + 1):
            target = chord[s * per_segment] + length * law(points[s][6], j / (share + 1))
            best = min(range(len(chord)), key=lambda i: (abs(chord[i] - target), i))
            shown.append((samples[best], chord[best] / chord[-1]))
    return shown


# Exact spacing (SPEC 4.3, 4.4): the same targets on the true arc length, each in-between the point at
# its target length. The length is integrated here by 5-point Gauss-Legendre on 64 pieces per
# segment (the program uses adaptive Simpson) and inverted by bisection on u to 1e-15.
GAUSS = [(-0.9061798459386640, 0.2369268850561891), (-0.5384693101056831, 0.4786286704993665),
         (0.0, 0.5688888888888889), (0.5384693101056831, 0.4786286704993665),
         (0.9061798459386640, 0.2369268850561891)]
PIECES = 64


def segments(points):
    n = len(points) - 1
    result = []
    for k in range(n):
        p0, p1 = points[k][:3], points[k + 1][:3]
        t0 = mul(sub(p1, p0), SLOPES[0]) if k == 0 else tangents(points, k)[1]
        t1 = mul(sub(p1, p0), SLOPES[1]) if k + 1 == n else tangents(points, k + 1)[0]
        result.append((p0, p1, t0, t1))
    return result


def point_on(segment, u):
    p0, p1, t0, t1 = segment
    return add(add(mul(p0, f1(u)), mul(p1, f2(u))), add(mul(t0, u**3 - 2 * u**2 + u), mul(t1, u**3 - u**2)))


def speed(segment, u):
    p0, p1, t0, t1 = segment
    d = add(add(mul(p0, 6 * u**2 - 6 * u), mul(p1, -6 * u**2 + 6 * u)),
            add(mul(t0, 3 * u**2 - 4 * u + 1), mul(t1, 3 * u**2 - 2 * u)))
    return math.sqrt(sum(x * x for x in d))


def length_to(segment, u_end):
    half = u_end / PIECES / 2
    return math.fsum(w * half * speed(segment, (2 * i + 1) * half + x * half)
                     for i in range(PIECES) for x, w in GAUSS)


def exact_inbetweens(points):
    parts = segments(points)
    to_point = [0.0]
    for segment in parts:
        to_point.append(to_point[-1] + length_to(segment, 1.0))
    spans = span_bounds(points)
    lengths = [to_point[e] - to_point[s] for s, e in spans]
    shown = []
    for (s, _), length, share in zip(spans, lengths, shares_by_largest_remainder(lengths, INBETWEENS)):
        for j in range(1, share + 1):
            target = to_point[s] + length * law(points[s][6], j / (share + 1))
            k = max(i for i in range(len(parts)) if to_point[i] <= target)
            low, high = 0.0, 1.0
            while high - low > 1e-15:
                middle = (low + high) / 2
                if to_point[k] + length_to(parts[k], middle) < target:
                    low = middle
                else:
                    high = middle
            shown.append(point_on(parts[k], (low + high) / 2))
    return shown


def edge(points, key1_point, key2_point, slopes=SLOPES, per_segment=SAMPLES, count=INBETWEENS):
    """Positions and progress of one edge path in frames 0 .. M+1."""
    shown = inbetweens(points, curve(points, slopes, per_segment), count, per_segment)
    return [key1_point] + [p for p, _ in shown] + [key2_point], [0.0] + [w for _, w in shown] + [1.0]


def place_along(key):
    """Normalised cumulative chord length (open graphic); a key whose points coincide: i/(n-1)."""
    chord = [0.0]
    for i in range(1, len(key)):
        chord.append(chord[-1] + math.dist(key[i - 1], key[i]))
    if chord[-1] == 0:
        return [i / (len(key) - 1) for i in range(len(key))]
    return [c / chord[-1] for c in chord]


def blend(key1, key2, first_edge, last_edge):
    """The surface-fitting blend of SPEC 5.3 (open graphic): frames 0 .. M+1 from the two edges."""
    (e0, w0), (e1, w1) = first_edge, last_edge
    v = [(a + b) / 2 for a, b in zip(place_along(key1), place_along(key2))]
    frames = []
    for k in range(len(e0)):
        d0 = sub(e0[k], lerp(key1[0], key2[0], w0[k]))
        d1 = sub(e1[k], lerp(key1[-1], key2[-1], w1[k]))
        frame = []
        for i in range(len(key1)):
            w = f1(v[i]) * w0[k] + f2(v[i]) * w1[k]
            frame.append(add(lerp(key1[i], key2[i], w), add(mul(d0, f1(v[i])), mul(d1, f2(v[i])))))
        frames.append(frame)
    return frames


def surface_frames():
    return blend(KEY1, KEY2, edge(POINTS, KEY1[0], KEY2[0]), edge(LAST_POINTS, KEY1[-1], KEY2[-1]))


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
    print("# inbetweens exact: the same with --spacing exact")
    for p in exact_inbetweens(POINTS):
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
