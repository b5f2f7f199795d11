#!/usr/bin/env python3
"""Where Synfig's renderer put the moving circle of an `apcs export --sif` document, frame by frame,
against where APCS says the point is. The circle is the document's only red (its other layers are
greys, white behind): a pixel's weight is its red less its larger other channel, which is the
circle's coverage of the pixel over any grey, so the weighted centroid is the circle's centre.

Usage: sif_centres.py SIF FRAME_PREFIX PRINT THETA PHI curve|frames
  SIF           the document (its width, height and view-box map pixels to the view plane)
  FRAME_PREFIX  Synfig's frames FRAME_PREFIX.0000.ppm, .0001.ppm, … (synfig -t ppm -o PREFIX.ppm)
  PRINT         `apcs path FILE --print` of the exported path: `curve` compares frame i with curve
                sample i (print it with --samples equal to --frames-per-span), `frames` with
                KEY1, the in-betweens and KEY2
  THETA PHI     the view the document was exported along (degrees)
Prints the frames compared and the largest distance as a fraction of the path's size in the view
plane; exit 1 when a frame is missing, has no circle, or lies 1e-3 of the size or more away."""
import glob
import math
import re
import sys

sif, prefix, printed, theta, phi, mode = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), sys.argv[6]
document = open(sif).read()
canvas = re.search(r'<canvas [^>]*width="(\d+)" height="(\d+)"[^>]*view-box="([^"]+)"', document)
width, height = int(canvas.group(1)), int(canvas.group(2))
left, top, right, bottom = (float(v) for v in canvas.group(3).split())

st, ct = math.sin(math.radians(theta)), math.cos(math.radians(theta))
sp, cp = math.sin(math.radians(phi)), math.cos(math.radians(phi))


def plane(x, y, z):
    """x_e, y_e of SPEC 4.5 before the perspective division."""
    return (-x * st + y * ct, -x * ct * cp - y * st * cp + z * sp)


sections = {}
current = None
for line in open(printed):
    if line.startswith("# "):
        current = sections.setdefault(line[2:].strip(), [])
    elif line.strip():
        current.append(plane(*(float(v) for v in line.split())))
curve = sections["curve"]
expected = curve if mode == "curve" else [curve[0]] + sections["inbetweens"] + [curve[-1]]
xs, ys = [p[0] for p in curve], [p[1] for p in curve]
size = max(max(xs) - min(xs), max(ys) - min(ys))


def read_ppm(name):
    data = open(name, "rb").read()
    header = re.match(rb"P6\s+(\d+)\s+(\d+)\s+(\d+)\s", data)
    w, h = int(header.group(1)), int(header.group(2))
    return w, h, data[header.end():]


def centre(name):
    w, h, pixels = read_ppm(name)
    if (w, h) != (width, height):
        sys.exit(f"FAILED: {name} is {w}x{h}, the document {width}x{height}")
    total = sx = sy = 0.0
    for i in range(0, len(pixels), 3):
        r, g, b = pixels[i], pixels[i + 1], pixels[i + 2]
        weight = r - max(g, b)
        if weight > 0:
            pixel = i // 3
            total += weight
            sx += weight * (pixel % w + 0.5)
            sy += weight * (pixel // w + 0.5)
    if total == 0:
        sys.exit(f"FAILED: {name} shows no circle")
    return (left + sx / total * (right - left) / width, top + sy / total * (bottom - top) / height)


frames = sorted(glob.glob(prefix + ".[0-9][0-9][0-9][0-9].ppm"))
if len(frames) != len(expected):
    sys.exit(f"FAILED: Synfig rendered {len(frames)} frames, APCS has {len(expected)} positions")
worst, worst_frame = 0.0, 0
for index, (name, want) in enumerate(zip(frames, expected)):
    got = centre(name)
    distance = math.hypot(got[0] - want[0], got[1] - want[1]) / size
    if distance > worst:
        worst, worst_frame = distance, index
print(f"{len(frames)} frames, the circle at most {worst:.2e} of the path's size from APCS's point (frame {worst_frame})")
sys.exit(0 if worst < 1e-3 else 1)
