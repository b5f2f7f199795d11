#pragma once

#include "apcs/raster/bitmap.h"
#include "apcs/raster/glyph_mapper.h"

#include <optional>

namespace apcs {

// --pixels (SPEC §7.2.1): whether the session's drawing area goes to the terminal as a picture
// (sixel or the kitty graphics protocol) instead of characters. `automatic` asks the terminal.
enum class PixelChoice : unsigned char { off, automatic, sixel, kitty };

// The size of one character cell in the terminal's own (screen) pixels.
struct CellPixels {
    int width = 0;
    int height = 0;
    bool operator==(const CellPixels&) const = default;
};

// The largest picture a terminal shows, in screen pixels (xterm draws no sixel picture wider or
// taller than its graphics limit, 1000x1000 by default, nor than its window).
struct PictureLimit {
    int width = 0;
    int height = 0;
    bool operator==(const PictureLimit&) const = default;
};

// Where the picture of the drawing area lies on the terminal and how large it is. The picture is
// whole cells (`columns` x `rows`, at cell `column`, row 0), so that the terminal never scales it
// and a band of it is whole cell rows; the raster's rows [0, raster_rows) fill its top-left
// `content_width` x `content_height` screen pixels and the rest of it is black.
struct PicturePlacement {
    int column = 0;  // first cell column, counted from the terminal's left edge
    int columns = 0; // cells across
    int rows = 0;    // cells down, from the terminal's top row
    CellPixels cell;
    int raster_rows = 0;    // raster rows shown: 0 … raster_rows − 1
    int content_width = 0;  // screen pixels the raster's width is scaled to
    int content_height = 0; // screen pixels its raster_rows are scaled to
    bool operator==(const PicturePlacement&) const = default;

    int pixel_width() const { return columns * cell.width; }
    int pixel_height() const { return rows * cell.height; }
};

// How many cells of `cell` pixels hold `pixels` pixels (the last one partly).
constexpr int cells_holding(int pixels, int cell) { return (pixels + cell - 1) / cell; }

// The cell rows of `area` (the terminal's cells that show the raster, render_cells) that show the
// raster rows above `raster_rows`, a raster of `raster_height` rows: the rows whose first pixel
// (cell_of_pixel's partition) is above raster_rows. At 80x24 the drawing area's 261 rows are 18.
int cell_rows_above(int raster_rows, int raster_height, CellArea area);

// The raster's rows [0, raster_rows) (a raster `raster_width` wide) as a picture in the top
// `cell_rows` rows of `area`, on cells of `cell` screen pixels: scaled by the smaller of the two
// scales that fit its width and its height (each raster row 1.5 times as tall as a raster column
// is wide: hercules::aspect_correction), then centred across the area in whole cells. With a
// `limit`, the picture's whole cells, and a sixel band's height rounded up to 6 (up to 5 rows more),
// stay within it: the cells are fewer. nullopt when a size is not positive (no cell size known, an
// empty area, a limit smaller than a cell).
std::optional<PicturePlacement> place_picture(CellArea area, int cell_rows, int raster_width, int raster_rows,
                                              CellPixels cell, std::optional<PictureLimit> limit = std::nullopt);

// The picture of `placement` drawn from `raster`: screen pixel (x, y) of the content is lit when
// any raster pixel under it is (max pooling, as map_to_cells does: a one-pixel line stays a line
// when the picture is smaller than the raster); pixels outside the content are dark.
Bitmap scale_to_picture(const Bitmap& raster, const PicturePlacement& placement);

// Cell rows [first, end) of a picture.
struct CellRowBand {
    int first = 0;
    int end = 0;
    bool operator==(const CellRowBand&) const = default;
};

// The cell rows (of `cell_height` pixels) that hold every pixel row where `now` differs from
// `sent`: the band to send again after a key. nullopt when nothing differs; the whole picture when
// the two differ in size.
std::optional<CellRowBand> changed_band(const Bitmap& sent, const Bitmap& now, int cell_height);

} // namespace apcs
