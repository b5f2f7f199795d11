#pragma once

#include "apcs/raster/bitmap.h"
#include "apcs/raster/cell_grid.h"

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace apcs {

// How raster pixels become characters (SPEC §7.2).
enum class GlyphSet {
    automatic, // braille under a UTF-8 locale, else ascii (resolved by the caller)
    ascii,     // per cell the printable ASCII glyph whose shape best matches the pixels
    braille,   // 2x4 dots per cell (U+2800 …)
    blocks,    // 2x2 quadrant blocks per cell (U+2580 …)
};

// The character screen the raster is shown on: 80x24 cells (9x14.5 pixels of the raster each),
// what terminal emulators and SSH clients open with.
inline constexpr int text_screen_columns = 80;
inline constexpr int text_screen_rows = 24;
// The fewest rows the screen is shown on: one less than 80x24 (screens/short_screen.h), what tmux or screen
// leaves under its status line.
inline constexpr int short_screen_rows = text_screen_rows - 1;

struct CellArea {
    int columns = 0;
    int rows = 0;
};

// The largest area within a terminal of `columns` x `rows` that keeps the 80x24 proportions of
// the screen; 80x23 (the short screen) on a terminal of 23 rows and 80 columns or more; nullopt
// when the terminal is smaller than 80x23.
std::optional<CellArea> fit_cell_area(int columns, int rows);

// Remembers the ASCII choice for each pooled mask seen, since a screen repeats few shapes and
// matching one against the font costs far more than a look-up. Owned by whoever maps screens
// again and again (the terminal shell).
class AsciiGlyphCache {
public:
    char32_t glyph_for(unsigned pooled_mask);

private:
    std::unordered_map<unsigned, char32_t> m_glyphs;
};

// The cell (of `cells` across `pixels`) that holds pixel `pixel`: cell c covers the pixels from
// c·pixels/cells (rounded down) up to the next cell's start, the partition map_to_cells uses.
constexpr int cell_of_pixel(int pixel, int pixels, int cells)
{
    return pixels <= 0 ? 0 : ((pixel + 1) * cells + pixels - 1) / pixels - 1;
}

// Maps the whole bitmap onto `area`, each cell covering its share of the pixels. Sub-blocks of a
// cell are lit when any of their pixels is (max pooling), so 1-pixel lines survive; a cell is a
// space only when none of its pixels is lit.
CellGrid map_to_cells(const Bitmap& bitmap, CellArea area, GlyphSet glyphs);
CellGrid map_to_cells(const Bitmap& bitmap, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache);

} // namespace apcs
