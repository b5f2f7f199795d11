#!/usr/bin/env python3
"""Whether a picture (8-bit grey, PICTURE_WIDTH wide) lies pixel for pixel in a screenshot (8-bit
grey, SCREEN_WIDTH wide) with its top left corner within MAX_OFFSET pixels of the screen's. Prints
where and exits 0; else prints the fewest differing rows found and exits 1.
Usage: find_picture.py SCREEN SCREEN_WIDTH PICTURE PICTURE_WIDTH MAX_OFFSET"""
import sys

screen, screen_width = open(sys.argv[1], "rb").read(), int(sys.argv[2])
picture, width = open(sys.argv[3], "rb").read(), int(sys.argv[4])
rows = len(picture) // width
fewest = None
for top in range(int(sys.argv[5]) + 1):
    for left in range(int(sys.argv[5]) + 1):
        starts = [(top + y) * screen_width + left for y in range(rows)]
        wrong = sum(1 for y, start in enumerate(starts) if screen[start:start + width] != picture[y * width:(y + 1) * width])
        if wrong == 0:
            print(f"at +{left}+{top}: all {width}x{rows} pixels, {sum(1 for v in picture if v)} lit")
            sys.exit(0)
        fewest = wrong if fewest is None else min(fewest, wrong)
print(f"not found: at best {fewest} of {rows} rows differ")
sys.exit(1)
