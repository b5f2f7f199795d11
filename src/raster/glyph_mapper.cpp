#include "apcs/raster/glyph_mapper.h"

#include "apcs/raster/font.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>
#include <string_view>

namespace apcs {

namespace {

constexpr int ascii_pool_columns = 3;
constexpr int ascii_pool_rows = 7;

// ASCII candidates in order of preference on equal cost: line-like symbols first, so that a thin
// stroke becomes a stroke. Letters other than these shape-like few read as words, not lines.
constexpr std::u32string_view ascii_preference = U".-|/\\_'`,:;=+x<>^v()[]!\"*#oXLJTVY7{}%&@$?";

// Pools the pixel block [left, right) x [top, bottom) into columns x rows sub-blocks, each lit
// when any of its pixels is lit. Bit index: row·columns + column.
unsigned pool_block(const Bitmap& bitmap, int left, int top, int right, int bottom, int columns, int rows)
{
    unsigned mask = 0;
    const int width = std::max(right - left, 1);
    const int height = std::max(bottom - top, 1);
    for (int sub_row = 0; sub_row < rows; ++sub_row) {
        const int y0 = top + sub_row * height / rows;
        const int y1 = std::max(top + (sub_row + 1) * height / rows, y0 + 1);
        for (int sub_column = 0; sub_column < columns; ++sub_column) {
            const int x0 = left + sub_column * width / columns;
            const int x1 = std::max(left + (sub_column + 1) * width / columns, x0 + 1);
            bool lit = false;
            for (int y = y0; y < y1 && !lit; ++y)
                for (int x = x0; x < x1 && !lit; ++x)
                    lit = bitmap.get(x, y);
            if (lit)
                mask |= 1u << (sub_row * columns + sub_column);
        }
    }
    return mask;
}

// Each candidate glyph of the font pooled like a cell of the 80x25 screen (9x14 pixels).
struct GlyphMask {
    char32_t glyph;
    unsigned mask;
};

std::vector<GlyphMask> build_ascii_masks()
{
    Bitmap cell(Font::cell_width, Font::cell_height);
    std::vector<GlyphMask> masks;
    for (const char32_t glyph : ascii_preference) {
        cell.clear();
        for (int row = 0; row < Font::cell_height; ++row)
            for (int column = 0; column < Font::cell_width; ++column)
                cell.set(column, row, Font::pixel(glyph, column, row));
        masks.push_back({glyph, pool_block(cell, 0, 0, cell.width(), cell.height(), ascii_pool_columns, ascii_pool_rows)});
    }
    return masks;
}

std::size_t candidate_rank(char32_t glyph)
{
    const std::size_t rank = ascii_preference.find(glyph);
    return rank == std::u32string_view::npos ? ascii_preference.size() : rank;
}

const std::vector<GlyphMask>& ascii_masks()
{
    // Immutable after its first use: derived once from the font's constant data.
    static const std::vector<GlyphMask> masks = build_ascii_masks();
    return masks;
}

char32_t braille_glyph(unsigned mask)
{
    // Pool bit (row·2 + column) → braille dot bit: dots 1-3 left rows 0-2, 4-6 right rows 0-2,
    // 7 left row 3, 8 right row 3.
    constexpr std::array<unsigned, 8> dot_bit{0, 3, 1, 4, 2, 5, 6, 7};
    unsigned dots = 0;
    for (unsigned bit = 0; bit < 8; ++bit)
        if (mask & (1u << bit))
            dots |= 1u << dot_bit[bit];
    return dots == 0 ? U' ' : static_cast<char32_t>(0x2800 + dots);
}

char32_t quadrant_glyph(unsigned mask)
{
    // Index: upper-left 1, upper-right 2, lower-left 4, lower-right 8.
    constexpr std::array<char32_t, 16> quadrants{U' ',      U'\u2598', U'\u259D', U'\u2580', U'\u2596', U'\u258C',
                                                 U'\u259E', U'\u259B', U'\u2597', U'\u259A', U'\u2590', U'\u259C',
                                                 U'\u2584', U'\u2599', U'\u259F', U'\u2588'};
    return quadrants[mask & 0xF];
}

} // namespace

std::optional<CellArea> fit_cell_area(int columns, int rows)
{
    if (columns < text_screen_columns || rows < text_screen_rows)
        return std::nullopt;
    const int fitted_columns = std::min(columns, rows * text_screen_columns / text_screen_rows);
    const int fitted_rows = std::min(rows, fitted_columns * text_screen_rows / text_screen_columns);
    return CellArea{fitted_columns, fitted_rows};
}

namespace {

// The mask moved by whole sub-blocks; nullopt when a lit sub-block would leave the grid.
std::optional<unsigned> shifted(unsigned mask, int right, int down)
{
    unsigned moved = 0;
    for (int row = 0; row < ascii_pool_rows; ++row)
        for (int column = 0; column < ascii_pool_columns; ++column) {
            if (!(mask & (1u << (row * ascii_pool_columns + column))))
                continue;
            const int to_row = row + down;
            const int to_column = column + right;
            if (to_row < 0 || to_row >= ascii_pool_rows || to_column < 0 || to_column >= ascii_pool_columns)
                return std::nullopt;
            moved |= 1u << (to_row * ascii_pool_columns + to_column);
        }
    return moved;
}

} // namespace

char32_t ascii_glyph_for(unsigned pooled_mask)
{
    if (pooled_mask == 0)
        return U' ';
    // A stroke may sit anywhere in its cell while the font draws it at one place: the cell's
    // shape may move up to three sub-blocks up or down and one sideways, each step costing half
    // a wrong sub-block, so a line a band below the font's '-' is still '-' and not '='.
    char32_t best = U'#';
    int best_cost = 1 << 30;
    for (int down = -3; down <= 3; ++down)
        for (int right = -1; right <= 1; ++right) {
            const std::optional<unsigned> moved = shifted(pooled_mask, right, down);
            if (!moved)
                continue;
            const int move_cost = std::abs(down) + std::abs(right);
            for (const GlyphMask& candidate : ascii_masks()) {
                const int cost = 2 * std::popcount(candidate.mask ^ *moved) + move_cost;
                // Equal costs keep the earlier candidate: the preference order decides.
                if (cost < best_cost || (cost == best_cost && candidate_rank(candidate.glyph) < candidate_rank(best))) {
                    best_cost = cost;
                    best = candidate.glyph;
                }
            }
        }
    return best;
}

CellGrid map_to_cells(const Bitmap& bitmap, CellArea area, GlyphSet glyphs)
{
    CellGrid grid(area.columns, area.rows);
    if (area.columns <= 0 || area.rows <= 0)
        return grid;
    const int pool_columns = glyphs == GlyphSet::ascii ? ascii_pool_columns : 2;
    const int pool_rows = glyphs == GlyphSet::ascii ? ascii_pool_rows : glyphs == GlyphSet::blocks ? 2 : 4;
    for (int row = 0; row < area.rows; ++row) {
        const int top = row * bitmap.height() / area.rows;
        const int bottom = (row + 1) * bitmap.height() / area.rows;
        for (int column = 0; column < area.columns; ++column) {
            const int left = column * bitmap.width() / area.columns;
            const int right = (column + 1) * bitmap.width() / area.columns;
            const unsigned mask = pool_block(bitmap, left, top, right, bottom, pool_columns, pool_rows);
            char32_t glyph = U' ';
            switch (glyphs) {
            case GlyphSet::braille:
                glyph = braille_glyph(mask);
                break;
            case GlyphSet::blocks:
                glyph = quadrant_glyph(mask);
                break;
            case GlyphSet::ascii:
            case GlyphSet::automatic:
                glyph = ascii_glyph_for(mask);
                break;
            }
            grid.set(column, row, glyph);
        }
    }
    return grid;
}

} // namespace apcs
