#pragma once

#include "apcs/raster/bitmap.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"

#include <string>
#include <vector>

namespace apcs {

// Text of graphics mode, placed in the 80x25 text cells of the DOS screen.
struct TextLine {
    int column = 0;
    int row = 0;
    std::string text; // UTF-8
};

// A symbol that stands for a drawn mark (a control point's x): in character cells the cell that
// holds `at` shows `glyph`, whatever the glyph set; the raster already has the mark drawn.
struct PixelMark {
    PixelPoint at;
    char32_t glyph = U'x';
};

// What graphics mode shows: the 720x348 raster and the text over it.
struct GraphicsScreen {
    Bitmap bitmap;
    std::vector<TextLine> text;
    std::vector<PixelMark> marks;
};

// The raster with its text drawn in the 9x14 font, as the Hercules card showed it (for PNG).
Bitmap render_raster(const GraphicsScreen& screen);

// The raster mapped to characters, with the text laid over it as real characters, each text cell
// at its share of the area (80x25 text cells scale with the area).
CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs);
CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache);

} // namespace apcs
