#!/usr/bin/env python3
"""What a terminal shows of the session's drawing area with --pixels, worked out from the monitor's
picture of the same screen (a --handout PNG, 720x522, as 8-bit grey): the cell rows of the drawing
area, each pixel the terminal's background (BACKGROUND) except the picture, centred in whole
cells, its lit pixels 255 and the rest 0 (SPEC §7.2.1: scaled by the smaller of the two scales,
each raster row 1.5 times as tall as a column is wide, one-pixel lines kept by max pooling).
An oracle written apart from the C++ (raster/pixel_picture.cpp) from the same rules.
With LIMIT_WIDTH LIMIT_HEIGHT (the largest sixel picture the terminal shows), the picture's whole
cells stay within them, its height 5 pixels under (a sixel band's rows are rounded up to 6).
Usage: pixel_oracle.py MONITOR_GREY CELL_WIDTH CELL_HEIGHT COLUMNS ROWS BACKGROUND OUT_GREY
                       [LIMIT_WIDTH LIMIT_HEIGHT]
Prints the expected picture's width and height and where it goes, in pixels."""
import sys

monitor = open(sys.argv[1], "rb").read()
cell_width, cell_height, columns, rows, background = (int(v) for v in sys.argv[2:7])
raster_width, raster_height, drawing_bottom = 720, 348, 259
assert len(monitor) == raster_width * 522, "the monitor's picture is 720x522"
# The raster row r is the monitor picture's row ceil(1.5 r) (its rows repeat 1, 2, 1, 2 ...).
raster = [monitor[((3 * r + 1) // 2) * raster_width:((3 * r + 1) // 2 + 1) * raster_width] for r in range(raster_height)]
# Below the boundary the picture is dark: the message row's text is curses' (its top rows fall in
# the drawing area's last cell row where the cell rows do not end with the boundary, e.g. 170x51).
raster = [row if r <= drawing_bottom else bytes(raster_width) for r, row in enumerate(raster)]

# The cells that show the raster keep the 80x24 proportions (glyph_mapper's fit_cell_area).
area_columns = min(columns, rows * 80 // 24)
area_rows = min(rows, area_columns * 24 // 80)
# The drawing area's cell rows: those whose first raster row is above the boundary's last row.
drawing_cells = sum(1 for r in range(area_rows) if r * raster_height // area_rows < drawing_bottom + 1)
shown_rows = drawing_cells * raster_height // area_rows
box_width, box_height = area_columns * cell_width, drawing_cells * cell_height
picture_box_width, picture_box_height = box_width, box_height
if len(sys.argv) > 9 and int(sys.argv[8]) > 0:
    picture_box_width = min(box_width, int(sys.argv[8]) // cell_width * cell_width)
    picture_box_height = min(box_height, (int(sys.argv[9]) - 5) // cell_height * cell_height)
# Scale s = min(box_width / 720, box_height / (1.5 shown_rows)), in whole pixels rounded down.
if picture_box_width * shown_rows * 3 <= picture_box_height * raster_width * 2:
    width, height = picture_box_width, picture_box_width * shown_rows * 3 // (2 * raster_width)
else:
    width, height = picture_box_height * raster_width * 2 // (3 * shown_rows), picture_box_height
left = (area_columns - (width + cell_width - 1) // cell_width) // 2 * cell_width


def span(target, targets, sources):
    first = target * sources // targets
    return first, max((target + 1) * sources // targets, first + 1)


out = bytearray([background]) * (box_width * box_height)
picture_columns = (width + cell_width - 1) // cell_width * cell_width
picture_rows = (height + cell_height - 1) // cell_height * cell_height
for y in range(picture_rows):
    for x in range(picture_columns):
        out[y * box_width + left + x] = 0
x_spans = [span(x, width, raster_width) for x in range(width)]
for y in range(height):
    first, end = span(y, height, shown_rows)
    pooled = [any(raster[r][x] for r in range(first, min(end, shown_rows))) for x in range(raster_width)]
    for x, (x_first, x_end) in enumerate(x_spans):
        if any(pooled[x_first:x_end]):
            out[y * box_width + left + x] = 255
open(sys.argv[7], "wb").write(out)
print(f"picture {width}x{height} at +{left}+0 in {box_width}x{box_height}")
