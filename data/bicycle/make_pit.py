"""Writes the bicycle's road and the path of its wheel centres (seed 003, fig. 3: the bicycle
slides through a pit, a "滑坑").

The road runs along y (z up, the scene seen face-on): flat, then a pit 12 wide and 1 deep,
z = -(1 - cos(2 pi (y - 6) / 12)) / 2 for 6 <= y <= 18, then flat again. A wheel of radius 1
touches it where its centre is the road offset by 1 along the normal: pit.dat holds that offset
curve every 0.5 from y = 0 to 24 as the control points of the KB path the bicycle's rear axle
rides (MOVE pit.dat ALIGN AHEAD 3.2: its front axle, 3.2 ahead, rides it too). road.dat draws the
road every 0.25 from y = -1 to 28, so that the front wheel has road under it to the end.

Run in data/bicycle: python3 make_pit.py  (the files are rewritten; the same bytes each time).
"""
import math

RADIUS = 1.0
PIT_START, PIT_WIDTH, PIT_DEPTH = 6.0, 12.0, 1.0


def road(y):
    if PIT_START <= y <= PIT_START + PIT_WIDTH:
        return -PIT_DEPTH * (1 - math.cos(2 * math.pi * (y - PIT_START) / PIT_WIDTH)) / 2
    return 0.0


def slope(y):
    if PIT_START <= y <= PIT_START + PIT_WIDTH:
        return -PIT_DEPTH * math.pi / PIT_WIDTH * math.sin(2 * math.pi * (y - PIT_START) / PIT_WIDTH)
    return 0.0


def wheel_centre(y):
    """The road point at y offset by the radius along the road's upward normal."""
    s = slope(y)
    norm = math.hypot(1.0, s)
    return y - RADIUS * s / norm, road(y) + RADIUS / norm


def write(name, heading, points):
    with open(name, "w") as out:
        out.write(heading)
        for y, z in points:
            out.write(f"0 {y:.6f} {z:.6f}\n")


def main():
    steps = [k * 0.5 for k in range(49)]
    write("pit.dat",
          "; The path of the bicycle's wheel centres: the road of road.dat offset by the wheel's radius 1\n"
          "; along its normal, every 0.5 of y (written by make_pit.py). The rear axle rides it; with\n"
          "; ALIGN AHEAD 3.2 the front axle does too.\n",
          [wheel_centre(y) for y in steps])
    write("road.dat",
          "; The road: flat, a pit 12 wide and 1 deep between y = 6 and 18 (seed 003's \"sliding pit\"),\n"
          "; flat again; every 0.25 of y (written by make_pit.py).\n",
          [(k * 0.25 - 1.0, road(k * 0.25 - 1.0)) for k in range(117)])


if __name__ == "__main__":
    main()
