#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/raster/bitmap.h"

#include <string>

namespace apcs {

// How a picture's pixels are shaped (SPEC §7.1). The Hercules pixel is about 1.5 times taller than
// wide (hence SCF = 1.5), so the raster seen on square pixels is squashed.
enum class PngShape {
    // As the monitor showed it: each row 1.5 pixels tall (720x348 becomes 720x522, rows repeated
    // nearest-neighbour), so what APCS drew square is square.
    monitor,
    // The bare raster, one pixel per raster pixel, with a pHYs chunk giving the pixel aspect
    // (pixels per unit x:y = 3:2) for viewers that honour it.
    raw,
};

// Which way round a picture's pixels are lit.
enum class PngInk {
    // Lit pixels white on black, as the monitor showed them.
    monitor,
    // Lit pixels black on white: ink on paper, for printing (--handout with --paper).
    paper,
};

// The rows of a picture of `raster_rows` rows in `shape`.
int png_rows(int raster_rows, PngShape shape);

// The raster row that picture row `row` shows: on the monitor rows 0 1 2 3 4 5 … show 0 0 1 2 2 3 ….
int raster_row_of(int row, PngShape shape);

// The bitmap as a PNG file's bytes (libpng): 8-bit greyscale, lit pixels white on black like the
// monitor, or black on white for `PngInk::paper`. On a libpng failure, its reason: "libpng: …"
// (never printed by libpng itself, which would write over the curses screen).
Expected<std::string> encode_png(const Bitmap& bitmap, PngShape shape, PngInk ink = PngInk::monitor);

} // namespace apcs
