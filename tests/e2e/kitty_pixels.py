#!/usr/bin/env python3
"""Decodes a kitty graphics protocol file (ESC _ G keys ; base64 ESC \\ commands, chunked with m=1)
and writes its picture as 8-bit grey (raw bytes, rows top to bottom) with its size on stderr.
f=24 (RGB), f=32 (RGBA) and f=100 (PNG, through ImageMagick) are read; a pixel that is not grey
or not opaque is an error, as the APCS picture is white on black. Usage: kitty_pixels.py FILE OUT"""
import base64
import re
import subprocess
import sys


def commands(data):
    found = re.findall(rb"\x1b_G([^;\x1b]*)(?:;([^\x1b]*))?\x1b\\", data)
    if not found:
        sys.exit("no kitty graphics command")
    return [(dict(item.split(b"=", 1) for item in keys.split(b",") if item), payload) for keys, payload in found]


def main():
    data = open(sys.argv[1], "rb").read()
    parsed = commands(data)
    first = parsed[0][0]
    if first.get(b"a") != b"T" or parsed[-1][0].get(b"m", b"0") != b"0":
        sys.exit("not one transmitted and shown picture: %r" % first)
    # Each chunk is base64 on its own (kitty accepts a chunk padded where it ends).
    payload = b"".join(base64.b64decode(chunk, validate=True) for _, chunk in parsed)
    form = int(first.get(b"f", b"32"))
    if form == 100:
        grey = subprocess.run(["convert", "png:-", "-colorspace", "gray", "-depth", "8", "gray:-"],
                              input=payload, capture_output=True, check=True).stdout
        open(sys.argv[2], "wb").write(grey)
        return
    step = {24: 3, 32: 4}[form]
    width, height = int(first[b"s"]), int(first[b"v"])
    if len(payload) != width * height * step:
        sys.exit("%d bytes of pixels for %dx%d f=%d" % (len(payload), width, height, form))
    grey = bytearray(width * height)
    for index in range(width * height):
        pixel = payload[index * step:index * step + step]
        if pixel[0] != pixel[1] or pixel[1] != pixel[2] or (step == 4 and pixel[3] != 255):
            sys.exit("pixel %d,%d is %s, not opaque grey" % (index % width, index // width, pixel.hex()))
        grey[index] = pixel[0]
    open(sys.argv[2], "wb").write(grey)
    print("%dx%d f=%d c=%s r=%s, %d chunks" % (width, height, form, first.get(b"c", b"-").decode(),
                                              first.get(b"r", b"-").decode(), len(parsed)), file=sys.stderr)


main()
