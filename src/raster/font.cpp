#include "apcs/raster/font.h"

#include <algorithm>
#include <iterator>

namespace apcs {

namespace {

#include "apcs/raster/font_data.inc"

static_assert(font_glyph_rows == Font::cell_height, "the font must be 14 rows high");

const FontGlyph* find_glyph(char32_t code_point)
{
    const auto found = std::lower_bound(std::begin(font_glyphs), std::end(font_glyphs), code_point,
                                        [](const FontGlyph& glyph, char32_t wanted) { return glyph.code_point < wanted; });
    if (found == std::end(font_glyphs) || found->code_point != code_point)
        return nullptr;
    return found;
}

bool is_box_drawing(char32_t code_point) { return code_point >= 0x2500 && code_point <= 0x259F; }

} // namespace

bool Font::has_glyph(char32_t code_point) { return find_glyph(code_point) != nullptr; }

bool Font::pixel(char32_t code_point, int column, int row)
{
    if (column < 0 || column >= cell_width || row < 0 || row >= cell_height)
        return false;
    const FontGlyph* glyph = find_glyph(code_point);
    if (glyph == nullptr)
        glyph = find_glyph(U'?');
    if (glyph == nullptr)
        return false;
    if (column == 8) {
        if (!is_box_drawing(code_point))
            return false;
        column = 7;
    }
    return (glyph->rows[row] & (0x80u >> column)) != 0;
}

} // namespace apcs
