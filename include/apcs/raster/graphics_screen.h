#pragma once

#include "apcs/raster/bitmap.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/stroke.h"

#include <string>
#include <vector>

namespace apcs {

// Text of graphics mode, placed in the 80x24 text cells of graphics mode (hercules::text_row_top).
struct TextLine {
    int column = 0;
    int row = 0;
    std::string text; // UTF-8
    CellStyle style = CellStyle::plain;
};

// What a mark stands for. Marks are kept apart from the raster's lines so that at any terminal size
// each is one readable character (SPEC §7.2), while pictures draw their pixel shapes.
enum class MarkKind {
    control_point, // `x`; pixels: an x of 5x5 (thesis Pre_Draw)
    inbetween,     // `*` in ascii, `•` elsewhere; pixels: a 3x3 square (Draw_Ani_Path)
    arrow,         // `>` in ascii, `→` elsewhere, in the cell left of `at`; pixels: an arrow
    staff_value,   // `O`; pixels: two short vertical lines around the value
    tangent_end,   // `+`: the free end of a tangent arrow (the handle); pixels: a plus of 5x5
};

// A mark at a raster pixel. A reverse-styled control point is one of the picked region: reverse
// video in a terminal, a box around it in a picture.
struct PixelMark {
    PixelPoint at;
    MarkKind kind = MarkKind::control_point;
    CellStyle style = CellStyle::plain;
};

// What graphics mode shows: the 720x348 raster of lines, the marks and the text over it. `strokes`
// holds the raster's lines as vector lines where the drawing recorded them (Painter::record_into),
// for pictures that scale (SVG).
struct GraphicsScreen {
    Bitmap bitmap;
    std::vector<TextLine> text;
    std::vector<PixelMark> marks;
    std::vector<Stroke> strokes;
};

// The character a mark shows in `glyphs`.
char32_t mark_glyph(MarkKind kind, GlyphSet glyphs);

// The raster with its marks' pixel shapes and its text drawn in the 9x14 font, as the Hercules
// card showed it (for PNG).
Bitmap render_raster(const GraphicsScreen& screen);

// The raster mapped to characters, then the marks and the text laid over it as real characters,
// each at its share of the area (80x24 text cells scale with the area). Marks take the cell their
// pixel falls in, control points before the others; two or more in-betweens in one cell show their
// count (2 … 9).
CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs);
CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache);

} // namespace apcs
