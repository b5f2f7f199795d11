#!/usr/bin/env python3
"""Share of a PNG's lit pixels that a rendering of its SVG lights within one pixel.

Usage: svg_coverage.py PICTURE.pgm RENDERED.pgm   (plain PGM, P2, the same size)
Prints "LIT COVERED SHARE". A pixel is lit when brighter than half of white: the SVG's lines are
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

    lit = [(x, y) for y in range(height) for x in range(width) if picture[y * width + x]]
    covered = sum(1 for x, y in lit if near_rendered(x, y))
    print(len(lit), covered, f'{covered / max(len(lit), 1):.4f}')


main()
