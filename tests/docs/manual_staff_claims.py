#!/usr/bin/env python3
"""The manual's sentences about the four-line staff, the second path and the scenes, held against the program.

Each claim runs the program - `apcs path … --print` on the N-to-L example's way1.dat, a session
replayed with --keys, `apcs play … --print` on a scene - measures what the sentence says (the path's
length, the angle of a corner, the gaps between frames, where a scene's frames stand), formats the
numbers as the manual writes them and requires that exact sentence in manual.txt (line breaks read as
spaces). A changed number in the manual, or a program that no longer does what it says, fails.

Usage: manual_staff_claims.py APCS MANUAL DATA_FOLDER   (prints each sentence it checked)
"""
import math
import os
import re
import subprocess
import sys
import tempfile


def path_print(apcs, path_file, *options):
    out = subprocess.run([apcs, "path", path_file, "--print", *options], check=True, capture_output=True,
                         text=True).stdout.split("\n")
    curve_at, inbetweens_at = out.index("# curve"), out.index("# inbetweens")
    rows = lambda lines: [tuple(map(float, line.split()[:3])) for line in lines if line.strip()]
    return rows(out[curve_at + 1:inbetweens_at]), rows(out[inbetweens_at + 1:])


def length(points):
    return sum(math.dist(a, b) for a, b in zip(points, points[1:]))


def angle(u, v):
    dot = sum(a * b for a, b in zip(u, v))
    return math.degrees(math.acos(max(-1.0, min(1.0, dot / (math.hypot(*u) * math.hypot(*v))))))


def minus(a, b):
    return tuple(x - y for x, y in zip(a, b))


SAMPLES = 2000  # per segment: the curve's direction at a control point read off its neighbouring samples


def derivatives_at_point_2(apcs, path_file, *options):
    """dP/du arriving at and leaving the middle control point, from its neighbouring samples."""
    curve, _ = path_print(apcs, path_file, "--samples", str(SAMPLES), *options)
    k = SAMPLES  # control point 2 is sample 1 x SAMPLES
    scale = lambda v: tuple(x * SAMPLES for x in v)
    return scale(minus(curve[k], curve[k - 1])), scale(minus(curve[k + 1], curve[k]))


def tangent_length_at_point_2(apcs, path_file, *options):
    """A central difference: exact to O(h^2) where the curve has one tangent (continuity 0)."""
    arriving, leaving = derivatives_at_point_2(apcs, path_file, *options)
    return math.hypot(*[(a + b) / 2 for a, b in zip(arriving, leaving)])


def crosses_itself(points):
    """Whether the polyline crosses itself in the plane of its first, middle and last point (way1.dat's
    control points lie in one plane, and so does its curve)."""
    origin, middle, last = points[0], points[len(points) // 2], points[-1]
    u = minus(middle, origin)
    u = tuple(x / math.hypot(*u) for x in u)
    w = minus(last, origin)
    w = minus(w, tuple(x * sum(a * b for a, b in zip(w, u)) for x in u))
    w = tuple(x / math.hypot(*w) for x in w)
    flat = [(sum(a * b for a, b in zip(minus(p, origin), u)), sum(a * b for a, b in zip(minus(p, origin), w)))
            for p in points]
    side = lambda a, b, c: (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    def cross(p, q, r, s):
        return side(p, q, r) * side(p, q, s) < 0 and side(r, s, p) * side(r, s, q) < 0
    segments = list(zip(flat, flat[1:]))
    return any(cross(*segments[i], *segments[j]) for i in range(len(segments)) for j in range(i + 2, len(segments)))


def distance_off_chord(points):
    start, end = points[0], points[-1]
    chord = minus(end, start)
    def off(point):
        v = minus(point, start)
        cross = (v[1] * chord[2] - v[2] * chord[1], v[2] * chord[0] - v[0] * chord[2], v[0] * chord[1] - v[1] * chord[0])
        return math.hypot(*cross) / math.hypot(*chord)
    return max(off(point) for point in points)


def first_span_cubic(apcs, way1, slope):
    """The first span's cubic P(u) = P0 + c1 u + c2 u^2 + c3 u^3, read off `apcs path --print`.

    Not from a first sample step: at end slope 0 the span leaves its start as u^2 (9, -12, 10), so a
    step of 1/2000 moves 2e-6, which the printed 6 decimals round to a wrong direction (60.9 degrees
    where the span turns 56.3). Four samples a segment instead: way1.dat's integers put every sample
    at a multiple of 1/64, printed exactly, and the span is one cubic, so its four forward differences
    give its coefficients exactly (the fifth sample must agree: the fourth difference is 0)."""
    curve, _ = path_print(apcs, way1, "--samples", "4", "--slopes", slope, "1")
    span = curve[:5]
    differences = [span]
    while len(differences) < 5:
        differences.append([minus(b, a) for a, b in zip(differences[-1], differences[-1][1:])])
    if math.hypot(*differences[4][0]) > 1e-5:
        raise SystemExit(f"the first span at end slope {slope} is no cubic: fourth difference {differences[4][0]}")
    d1, d2, d3 = (differences[k][0] for k in (1, 2, 3))
    # Newton's forward form in x = 4u: P = P0 + d1 x + d2 x(x-1)/2 + d3 x(x-1)(x-2)/6.
    c1 = tuple(4 * (a - b / 2 + c / 3) for a, b, c in zip(d1, d2, d3))
    c2 = tuple(16 * (b / 2 - c / 2) for b, c in zip(d2, d3))
    c3 = tuple(64 * c / 6 for c in d3)
    return c1, c2, c3


def leading(*terms):
    """The first term that is not zero: the direction a curve leaves along where its tangent is 0."""
    return next(term for term in terms if math.hypot(*term) > 1e-9)


def vector_text(v):
    return "(" + ", ".join(f"{round(c, 6) + 0.0:g}" for c in v) + ")"


def turning(c1, c2, c3, steps=20000):
    """From start to end, and along the way, in degrees: the angle between the direction at the start
    and at the end, and the turns between successive directions summed into runs, a new run where the
    turning changes its sense (the span bends one way, then the other)."""
    derivative = lambda u: tuple(a + 2 * b * u + 3 * c * u * u for a, b, c in zip(c1, c2, c3))
    start = leading(c1, c2, c3)
    directions = [start] + [derivative(i / steps) for i in range(1, steps + 1)]
    runs, sense = [0.0], None
    for a, b in zip(directions, directions[1:]):
        normal = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
        if math.hypot(*normal) > 1e-12:
            if sense is not None and sum(x * y for x, y in zip(normal, sense)) < 0:
                runs.append(0.0)
            sense = normal
        runs[-1] += angle(a, b)
    return angle(start, directions[-1]), [run for run in runs if run >= 0.005]


def end_slope_claim(apcs, way1):
    """The first span's directions at its ends, its turn from start to end and in all, and its bulge,
    at end slopes 0 and 1."""
    measured = {}
    for slope in ("0", "1"):
        c1, c2, c3 = first_span_cubic(apcs, way1, slope)
        ends_along = leading(tuple(a + 2 * b + 3 * c for a, b, c in zip(c1, c2, c3)),
                             tuple(b + 3 * c for b, c in zip(c2, c3)))
        measured[slope] = (vector_text(leading(c1, c2, c3)), vector_text(ends_along), *turning(c1, c2, c3))

    def turns(net, runs):
        if len(runs) == 1:
            return f"turns {net:.2f} degrees, all one way"
        ways = ", then ".join(f"{run:.2f} {'one way' if i == 0 else 'the other'}" for i, run in enumerate(runs))
        return f"turns {net:.2f} degrees from its start to its end but {sum(runs):.2f} in all ({ways})"

    start0, end0, *turn0 = measured["0"]
    start1, end1, *turn1 = measured["1"]
    more = "more" if turn0[0] > turn1[0] else "less"
    in_all = "though less in all" if sum(turn0[1]) < sum(turn1[1]) else "and more in all"
    ends1 = "" if end1 == end0 else f", ends along {end1}"

    def first_span(slope):
        curve, _ = path_print(apcs, way1, "--samples", str(SAMPLES), "--slopes", slope, "1")
        return curve[:SAMPLES + 1]
    bulge = {f"{distance_off_chord(first_span(slope)):.3f}" for slope in ("0", "1")}
    off = " or ".join(sorted(bulge))  # one number when the slope changes nothing, as the manual says
    return (f"On way1.dat end slope 0 makes the first span turn {more} from its start to its end, {in_all}: "
            f"it starts along {start0}, ends along {end0} and {turns(*turn0)}; with slope 1 it starts along "
            f"{start1}{ends1} and {turns(*turn1)}; with either slope it lies at most {off} off its chord")


# KEY1, KEY2 and the view as offered; the first path: global control, tension +0.15, the other lines
# kept, accepted (N); Y; the second path: global control, every line kept as it starts, accepted. The
# script ends at step 6, having written both path files with their t c b a columns.
SECOND_PATH_KEYS = """ENTER
ENTER
ENTER
TEXT first.dat
ENTER
ENTER
8
6 6 6 ENTER
ENTER ENTER ENTER
N
Y
TEXT second.dat
ENTER
ENTER
8
ENTER ENTER ENTER ENTER
N
"""


def second_path_staff(apcs, keys, first, second, *options):
    """The staff values (t c b a) the second path's file is written with when the session's second path
    is accepted as it starts, after the first path's tension was set to +0.15."""
    with tempfile.TemporaryDirectory() as folder:
        for name, text in {**keys, "first.dat": first, "second.dat": second, "s.keys": SECOND_PATH_KEYS}.items():
            with open(os.path.join(folder, name), "w") as out:
                out.write(text)
        program = os.path.abspath(apcs) if os.sep in apcs else apcs  # run in the folder: a relative name moves
        subprocess.run([program, "--keys", "s.keys", *options], cwd=folder, check=True, capture_output=True,
                       stdin=subprocess.DEVNULL)
        def staff_of(name):
            with open(os.path.join(folder, name)) as written:
                rows = [line.split() for line in written if line.strip() and line[0] not in ";#S"]
            return tuple(float(value) for value in rows[0][3:7])
        return staff_of("first.dat"), staff_of("second.dat")


def second_path_claim(apcs, data):
    """Step 5: whose staff values the second path starts at, for a closed graphic and for N to L."""
    ring = {"key1.dat": "PART ring CLOSED\n0 0 0\n0 2 0\n0 2 2\n0 0 0\n",
            "key2.dat": "PART ring CLOSED\n4 0 0\n4 3 0\n4 3 3\n4 0 0\n"}
    ring_path = "0 0 0\n4 0 0\n"  # the ring's first point (and its last) from KEY1 to KEY2
    n_to_l = {}
    for name in ("key1.dat", "key2.dat", "way1.dat", "way4.dat"):
        with open(os.path.join(data, "n-to-l", name)) as source:
            n_to_l[name] = source.read()
    keys = {name: n_to_l[name] for name in ("key1.dat", "key2.dat")}
    options = ("--tension", "0.2", "--continuity", "0.1", "--bias", "-0.1", "--accel", "0.05")
    given = tuple(float(value) for value in options[1::2])

    def starts(first, second):  # the first path's tension is +0.15: never 0
        if second == first:
            return "those of the first"
        return "0" if second == (0.0, 0.0, 0.0, 0.0) else f"{second}"
    closed = starts(*second_path_staff(apcs, ring, ring_path, ring_path))
    opened = starts(*second_path_staff(apcs, keys, n_to_l["way1.dat"], n_to_l["way4.dat"]))
    first, second = second_path_staff(apcs, keys, n_to_l["way1.dat"], n_to_l["way4.dat"], *options)
    when_given = "when given" if second == given and first != given else f"not as given: {second}"
    # A second path file with its own columns: they come first, for a closed graphic too.
    own = "0 0 0 -0.25 0.5 0 0\n4 0 0 -0.25 0.5 0 0\n"
    _, closed_own = second_path_staff(apcs, ring, ring_path, own)
    _, open_own = second_path_staff(apcs, keys, n_to_l["way1.dat"],
                                    "".join(line.rstrip("\n") + " -0.25 0.5 0 0\n" for line in
                                            n_to_l["way4.dat"].splitlines(True) if line.strip()
                                            and not line.startswith(";")))
    columns = "first either way" if closed_own == open_own == (-0.25, 0.5, 0.0, 0.0) else "second"
    return (f"For a closed graphic only, the second path's staff values start at {closed}; an open graphic's "
            f"second path (N to L) starts at {opened} (or at --tension, --continuity, --bias and --accel, "
            f"{when_given}). A path file's own t c b a columns come {columns}")


def scene_frames(apcs, scene, drawings=None, *options):
    """`apcs play --print` of a scene: each frame's points, object by object. A scene given as text is
    written with its drawings into a fresh folder; else it is a file's name."""
    with tempfile.TemporaryDirectory() as folder:
        if drawings is not None:
            for name, text in {"scene.scn": scene, **drawings}.items():
                with open(os.path.join(folder, name), "w") as out:
                    out.write(text)
            scene = os.path.join(folder, "scene.scn")
        lines = subprocess.run([apcs, "play", scene, "--print", *options], check=True, capture_output=True,
                               text=True).stdout.split("\n")
    frames = []
    for line in lines:
        if line.startswith("# frame"):
            frames.append({})
        elif line.startswith("# object"):
            points = frames[-1].setdefault(line.split()[2], [])
        elif line.strip():
            points.append(tuple(map(float, line.split()[:3])))
    return frames


SQUARE = [(0, -1, -1), (0, 1, -1), (0, 1, 1), (0, -1, 1)]  # 2x2, centred at 0, face-on


def turned(point, degrees, about):
    """By the right-hand rule about +x (ROTATE's default axis) through ABOUT."""
    a = math.radians(degrees)
    x, y, z = minus(point, about)
    return (about[0] + x, about[1] + y * math.cos(a) - z * math.sin(a), about[2] + y * math.sin(a) + z * math.cos(a))


def scaled(point, factors, about):
    """By one factor, or by three: x, y and z."""
    factors = list(factors) * 3 if len(factors) == 1 else factors
    return tuple(c + f * (p - c) for p, f, c in zip(point, factors, about))


def frames_in(f, span):
    return max(0, min(f, span[1]) - span[0])


def scale_then_turn(point, f, rotate, scale):
    """The closed form: the drawing scaled by all of its SCALE up to frame f, then turned by all of its turn."""
    (degrees, turn_about, turn_span), (factors, scale_about, scale_span) = rotate, scale
    k = frames_in(f, scale_span)
    return turned(scaled(point, [c ** k for c in factors], scale_about), degrees * frames_in(f, turn_span), turn_about)


def ticks_per_axis(point, f, rotate, scale):
    """Every tick scaling along the scene's axes first, then turning, both about the centre 0."""
    (degrees, _, turn_span), (factors, _, scale_span) = rotate, scale
    for g in range(1, f + 1):
        point = turned(scaled(point, factors if frames_in(g, scale_span) > frames_in(g - 1, scale_span) else (1, 1, 1),
                              (0, 0, 0)),
                       degrees if frames_in(g, turn_span) > frames_in(g - 1, turn_span) else 0, (0, 0, 0))
    return point


def scene_line(keyword, values, about, span):
    where = "" if about == (0, 0, 0) else " ABOUT " + " ".join(f"{c:g}" for c in about)
    return f"{keyword} {' '.join(f'{v:g}' for v in values)}{where} FROM {span[0]} TO {span[1]}\n"


CENTRE, ON_AXIS = (0, 0, 0), (4, 0, 0)  # a point on the turn's axis (x) through the centre
TURN_OFF, SCALE_OFF = (0, 5, 0), (0, 0, 3)
ORDERS = {"turn first": ((0, 2), (2, 4)), "together": ((0, 4), (0, 4)), "scale first": ((2, 4), (0, 2))}


def accumulation_cases():
    """Every ROTATE 10 with a SCALE, each about the centre, a point on the turn's axis or off it, with one
    factor or three, the turn before, with or after the scaling: name -> (rotate, scale)."""
    cases = {}
    for order, (turn_span, scale_span) in ORDERS.items():
        for turn_about in (CENTRE, ON_AXIS, TURN_OFF):
            for scale_about in (CENTRE, ON_AXIS, SCALE_OFF):
                cases[f"one factor, turn about {turn_about}, scale about {scale_about}, {order}"] = (
                    (10, turn_about, turn_span), ((1.1,), scale_about, scale_span))
        for factors in ((1, 1.1, 1), (1.1, 1, 1)):
            cases[f"factors {factors} about the centre, {order}"] = ((10, CENTRE, turn_span),
                                                                     (factors, CENTRE, scale_span))
    return cases


def departs_by_the_manual(rotate, scale):
    """The manual's rule: when the ticks are not "scale, then turn"."""
    (_, turn_about, turn_span), (factors, scale_about, scale_span) = rotate, scale
    order = next(name for name, spans in ORDERS.items() if spans == (turn_span, scale_span))
    if len(factors) == 1:
        off_axis = lambda point: point[1] != 0 or point[2] != 0
        return order != "turn first" and (off_axis(turn_about) or off_axis(scale_about))
    return factors[1] != factors[2] and order != "scale first"


def accumulation_claims(apcs):
    """Section 20: the ticks against "scale, then turn", case by case, and the figures of the 2x2 square."""
    cases = accumulation_cases()
    scene = "FRAMES 4\n" + "".join(
        f"OBJECT square{i}\nSHAPE square.dat\n" + scene_line("ROTATE", rotate[:1], *rotate[1:]) +
        scene_line("SCALE", *scale) for i, (rotate, scale) in enumerate(cases.values()))
    frames = scene_frames(apcs, scene, {"square.dat": "".join(f"{x} {y} {z}\n" for x, y, z in SQUARE)})
    def off(i, law, f):
        rotate, scale = list(cases.values())[i]
        shown = frames[f][f"square{i}"]
        return max(math.dist(point, law(given, f, rotate, scale)) for point, given in zip(shown, SQUARE))
    names = list(cases)
    wrong = [name for i, name in enumerate(names) if
             (max(off(i, scale_then_turn, f) for f in range(5)) > 1e-4) != departs_by_the_manual(*cases[name])]
    per_axis_together = names.index("factors (1, 1.1, 1) about the centre, together")
    by_ticks = max(off(per_axis_together, ticks_per_axis, f) for f in range(5))
    yield (("Each tick scales the body along the scene's axes first, then turns it: a per-axis SCALE (three "
            "factors) is applied before the turn") if by_ticks < 1e-5 else
           f"the ticks of a per-axis SCALE with a turn are {by_ticks:.3f} from scaling first, then turning")
    yield ('The ticks add up to "scale, then turn" (the drawing scaled by all of its SCALE so far, then turned by '
           'all of its turn so far) but for two cases. With one factor they depart from it whenever a turn comes '
           "during or after the scaling and the turn or the SCALE is about a point off the turn's axis through "
           "the centre (the pivots' offsets turn and scale with the body); a turn over before the scaling "
           "starts, or both about the centre, keep to it. A per-axis SCALE whose factors across the turn's axis "
           "differ departs from it whenever it comes during or after a turn, even with both about the centre "
           "(it stretches the turned body along the scene's axes); before the turn, both about the centre, it "
           "keeps to it" if not wrong else "the rule does not hold for: " + "; ".join(wrong))
    both_off = names.index(f"one factor, turn about {TURN_OFF}, scale about {SCALE_OFF}, together")
    turn_off = names.index(f"one factor, turn about {TURN_OFF}, scale about {CENTRE}, together")
    figures = lambda i, frames_shown: [f"{off(i, scale_then_turn, f):.3f}" for f in frames_shown]
    both, turn, per_axis = figures(both_off, (1, 3)), figures(turn_off, (1, 2, 3)), figures(per_axis_together, (1, 2))
    yield (f"A 2x2 square centred at 0 with ROTATE 10 ABOUT 0 5 0 and SCALE 1.1 ABOUT 0 0 3 stands {both[0]} from "
           f"that composition after one frame and {both[1]} after three, where the seed's tick puts it; with "
           f"SCALE 1.1 about its centre instead (only the turn off-centre), it stands {turn[0]}, {turn[1]} and "
           f"{turn[2]} off after one, two and three frames; with ROTATE 10 and SCALE 1 1.1 1, both about its "
           f"centre, {per_axis[0]} after one frame and {per_axis[1]} after two")


def face_on_turn(before, after):
    """How far a rigid drawing turned clockwise face-on (seen along x, y right, z up) between two frames,
    in radians: the turn of the line from its first point to its farthest one."""
    far = max(range(len(before)), key=lambda j: math.dist(before[j], before[0]))
    a, b = minus(before[far], before[0]), minus(after[far], after[0])
    return -math.remainder(math.atan2(b[2], b[1]) - math.atan2(a[2], a[1]), 2 * math.pi)


def bicycle_claim(apcs, data):
    """Section 20's bicycle: the pedals' turn in every frame against their own hub's travel and the wheels'
    turns (ROLL 1, the wheels' radius, for all three: bicycle.scn)."""
    frames = scene_frames(apcs, os.path.join(data, "bicycle", "bicycle.scn"))
    start = frames[0]["pedals"]
    hub = tuple((min(c) + max(c)) / 2 for c in zip(*start))  # ROLL's hub: the middle of the frame-0 drawing
    turned_so_far, own_hub, apart = 0.0, 0.0, {"rear-wheel": 0.0, "front-wheel": 0.0}
    hub_then = hub
    for then, now in zip(frames, frames[1:]):
        turn = face_on_turn(then["pedals"], now["pedals"])
        turned_so_far += turn
        # Where the hub went: the rigid drawing's first point, plus the hub's frame-0 offset turned with it.
        y, z = minus(hub, start[0])[1:]
        c, s = math.cos(-turned_so_far), math.sin(-turned_so_far)
        hub_now = (now["pedals"][0][0], now["pedals"][0][1] + y * c - z * s, now["pedals"][0][2] + y * s + z * c)
        travel = math.dist(hub_then, hub_now)
        own_hub = max(own_hub, abs(turn - travel) / travel)
        hub_then = hub_now
        for wheel in apart:
            wheel_turn = face_on_turn(then[wheel], now[wheel])
            apart[wheel] = max(apart[wheel], abs(turn - wheel_turn) / wheel_turn)
    rolls = "roll on their own hub's travel" if own_hub < 1e-3 else f"slip {100 * own_hub:.1f} % on their own hub"
    return (f"pedals {rolls}, as the seed turns all three alike, and the bicycle's tilt in the pit moves each hub a "
            f"little differently, so a frame's turn of the pedals is within {100 * apart['rear-wheel']:.1f} % of the "
            f"rear wheel's and {100 * apart['front-wheel']:.1f} % of the front wheel's")


def claims(apcs, data):
    way1 = f"{data}/n-to-l/way1.dat"
    with open(way1) as source:
        points = [tuple(map(float, line.split()[:3])) for line in source if line.strip() and not line.startswith(";")]
    incoming, outgoing = minus(points[1], points[0]), minus(points[2], points[1])

    yield (f"tension +0.15 shortens the tangent at control point 2 from "
           f"{tangent_length_at_point_2(apcs, way1):.2f} to "
           f"{tangent_length_at_point_2(apcs, way1, '--tension', '0.15'):.2f} units")

    corner = angle(*derivatives_at_point_2(apcs, way1, "--continuity", "-1"))
    smooth = angle(*derivatives_at_point_2(apcs, way1))
    yield (f"continuity -1 breaks the curve at control point 2 into a corner of {corner:.0f} degrees "
           f"(at 0 it turns {smooth:.0f} degrees there)")

    spike = angle(*derivatives_at_point_2(apcs, way1, "--continuity", "1"))
    curve, _ = path_print(apcs, way1, "--samples", "200", "--continuity", "1")
    shape = "a loop" if crosses_itself(curve) else "not a loop"
    yield f"continuity +1 swaps the two tangents and makes a spike of {spike:.0f} degrees at control point 2, {shape}"

    for bias in (1, -1):
        _, leaving = derivatives_at_point_2(apcs, way1, "--bias", str(bias))
        yield (f"with bias {bias:+d} the curve leaves control point 2 {angle(leaving, incoming):.0f} degrees off "
               f"the incoming chord and {angle(leaving, outgoing):.0f} off the outgoing")

    yield end_slope_claim(apcs, way1)
    yield second_path_claim(apcs, data)

    curve, inbetweens = path_print(apcs, way1, "--tension", "0.15", "--accel", "0.15")
    along = [0.0]
    for a, b in zip(curve, curve[1:]):
        along.append(along[-1] + math.dist(a, b))
    place = {point: distance for point, distance in zip(curve, along)}
    frames = [0.0] + [place[point] for point in inbetweens] + [along[-1]]
    gaps = [b - a for a, b in zip(frames, frames[1:])]
    yield (f"along the path the first gap between frames is {gaps[0]:.2f} units and the last {gaps[-1]:.2f}: "
           f"the * marks crowd toward KEY1, where the point now starts slowly")

    yield from accumulation_claims(apcs)
    yield bicycle_claim(apcs, data)


def main():
    apcs, manual, data = sys.argv[1:4]
    with open(manual) as text:
        flowing = re.sub(r"\s+", " ", text.read())
    failed = 0
    for sentence in claims(apcs, data):
        if sentence in flowing:
            print("ok:", sentence)
        else:
            print("FAILED: manual.txt does not say:", sentence)
            failed += 1
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
