#!/usr/bin/env python3
"""Share of a PNG's lit pixels that a rendering of its SVG lights within one pixel.

Usage: svg_coverage.py PICTURE.pgm RENDERED.pgm [FIRST_ROW END_ROW]   (plain PGM, P2, the same size)
Prints "LIT COVERED SHARE", counting the PICTURE's lit pixels in rows FIRST_ROW <= y < END_ROW
(all rows when not given). A pixel is lit when brighter than half of white: the SVG's lines are
anti-aliased, the PNG's are black and white.
"""
import sys


def read_plain_pgm(path):
    words = open(path, 'rb').read().split()
    if words[0] != b'P2':
        sys.exit(f'{path}: not a plain PGM (P2)')
    width, height, white = int(words[1]), int(words[2]), int(words[3])
    values = words[4:4 + width * height]
    lit = [int(value) * 2 > white for value in values]
    return width, height, lit


def main():
    width, height, picture = read_plain_pgm(sys.argv[1])
    rendered_width, rendered_height, rendered = read_plain_pgm(sys.argv[2])
    if (width, height) != (rendered_width, rendered_height):
        sys.exit(f'sizes differ: {width}x{height} and {rendered_width}x{rendered_height}')

    def near_rendered(x, y):
        return any(0 <= x + dx < width and 0 <= y + dy < height and rendered[(y + dy) * width + x + dx]
                   for dy in (-1, 0, 1) for dx in (-1, 0, 1))

    first_row, end_row = (int(sys.argv[3]), int(sys.argv[4])) if len(sys.argv) > 4 else (0, height)
    lit = [(x, y) for y in range(max(first_row, 0), min(end_row, height)) for x in range(width)
           if picture[y * width + x]]
    covered = sum(1 for x, y in lit if near_rendered(x, y))
    print(len(lit), covered, f'{covered / max(len(lit), 1):.4f}')


main()
