#pragma once

#include <cstdint>

namespace apcs {

struct FontGlyph {
    char32_t code_point;
    std::uint8_t rows[14];
};

// The raster's text font: the IBM VGA 8x14 font of Debian's console-setup-linux
// (Lat15-VGA14.psf), converted at build time, drawn in 9x14 cells. As on the MDA and Hercules
// cards, the 9th column repeats the 8th for the box-drawing range U+2500–U+259F and is blank for
// everything else. Code points the font lacks are drawn as '?'.
class Font {
public:
    static constexpr int cell_width = 9;
    static constexpr int cell_height = 14;

    // Whether pixel (column, row) of the 9x14 cell of `code_point` is lit.
    static bool pixel(char32_t code_point, int column, int row);
    static bool has_glyph(char32_t code_point);
};

} // namespace apcs
