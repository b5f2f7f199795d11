#pragma once

#include "apcs/geometry/pixel_point.h"
#include "apcs/raster/graphics_screen.h"

#include <string>

namespace apcs {

// An SVG picture is drawn as the monitor showed the raster (SPEC §7.1): 720 wide, rows 1.5 units
// tall (720x522), so that what APCS drew square is square.
inline constexpr double svg_row_height = 1.5;

// Where the centre of raster pixel `pixel` lies in the SVG picture, as its points attributes
// write it: "X,Y" with X = x + 0.5 and Y = (y + 0.5) × 1.5, in the shortest decimal form.
std::string svg_point_text(PixelPoint pixel);

// The screen as an SVG document, white on black like the PNG: each recorded stroke as one <path>
// (class "solid", "dashed" or "dotted", and "clipped" when the drawing was clipped to a rectangle)
// whose subpaths are the pieces the Painter lit: cut where the clip rectangle and the raster's
// edges cut the line, and dashed or dotted with the PNG's pattern and phase, so that every viewer
// draws what the PNG shows without clip paths or dash arrays; its marks as small vector shapes
// (class "mark": the x of 5x5, the 3x3 square, the arrow, the staff marker) and its text as
// <text> in a monospace font at its 9x14 cells. Lines the drawing did not record
// (GraphicsScreen::strokes) are not in it.
std::string encode_svg(const GraphicsScreen& screen);

} // namespace apcs
