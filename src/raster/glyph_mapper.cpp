#include "apcs/raster/glyph_mapper.h"

#include "apcs/raster/font.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace apcs {

namespace {

constexpr int ascii_pool_columns = 3;
constexpr int ascii_pool_rows = 7;

// ASCII candidates in order of preference on equal cost: line-like symbols only, so that a thin
// stroke becomes a stroke and nothing reads as a mark. The marks' characters (x X o O * > and the
// digits, SPEC §7.2), letters and blobs such as # @ $ % & ? are never used for line shapes.
constexpr std::u32string_view ascii_preference = U".-|/\\_'`,:;=+^()[]!\"{}";

// Whether any pixel of row y in [x0, x1) is lit, testing whole bytes at a time.
bool any_lit(const Bitmap& bitmap, int y, int x0, int x1)
{
    const std::uint8_t* row = bitmap.row(y);
    const int first_byte = x0 >> 3;
    const int last_byte = (x1 - 1) >> 3;
    for (int byte = first_byte; byte <= last_byte; ++byte) {
        unsigned mask = 0xFFu;
        if (byte == first_byte)
            mask &= 0xFFu >> (x0 & 7);
        if (byte == last_byte)
            mask &= 0xFFu << (7 - ((x1 - 1) & 7));
        if (row[byte] & mask)
            return true;
    }
    return false;
}

// Pools the pixel block [left, right) x [top, bottom) into columns x rows sub-blocks, each lit
// when any of its pixels is lit. Bit index: row·columns + column. The block lies in the bitmap.
unsigned pool_block(const Bitmap& bitmap, int left, int top, int right, int bottom, int columns, int rows)
{
    unsigned mask = 0;
    const int width = std::max(right - left, 1);
    const int height = std::max(bottom - top, 1);
    for (int sub_row = 0; sub_row < rows; ++sub_row) {
        const int y0 = std::min(top + sub_row * height / rows, bitmap.height() - 1);
        const int y1 = std::min(std::max(top + (sub_row + 1) * height / rows, y0 + 1), bitmap.height());
        for (int sub_column = 0; sub_column < columns; ++sub_column) {
            const int x0 = std::min(left + sub_column * width / columns, bitmap.width() - 1);
            const int x1 = std::min(std::max(left + (sub_column + 1) * width / columns, x0 + 1), bitmap.width());
            for (int y = y0; y < y1; ++y)
                if (any_lit(bitmap, y, x0, x1)) {
                    mask |= 1u << (sub_row * columns + sub_column);
                    break;
                }
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
    if (columns < text_screen_columns || rows < short_screen_rows)
        return std::nullopt;
    if (rows == short_screen_rows)
        return CellArea{text_screen_columns, short_screen_rows};
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

// Whether the pooled cell is a corner, a horizontal line ending in a vertical one: a band of at most
// two full sub-rows, and from it to the top or the bottom edge at least two sub-rows with only the
// left, or only the right, sub-column lit. The font has no corner: the nearest glyph was `[` at the
// top left of a frame and `_` or `-` at the other three.
bool is_corner(unsigned pooled_mask)
{
    constexpr unsigned full_row = (1u << ascii_pool_columns) - 1;
    const auto row_bits = [&](int row) { return (pooled_mask >> (row * ascii_pool_columns)) & full_row; };
    int band_top = 0;
    while (band_top < ascii_pool_rows && row_bits(band_top) != full_row)
        ++band_top;
    int band_bottom = band_top;
    while (band_bottom + 1 < ascii_pool_rows && row_bits(band_bottom + 1) == full_row)
        ++band_bottom;
    if (band_top == ascii_pool_rows || band_bottom - band_top >= 2)
        return false;
    // The rows [from, to) are the vertical line's, in one edge column; the others are empty.
    const auto is_stem = [&](int from, int to) {
        if (to - from < 2)
            return false;
        for (const unsigned column : {1u, 1u << (ascii_pool_columns - 1)}) {
            bool stem = true;
            for (int row = 0; row < ascii_pool_rows && stem; ++row) {
                const bool in_band = row >= band_top && row <= band_bottom;
                if (!in_band)
                    stem = row_bits(row) == (row >= from && row < to ? column : 0u);
            }
            if (stem)
                return true;
        }
        return false;
    };
    return is_stem(0, band_top) || is_stem(band_bottom + 1, ascii_pool_rows);
}

// The ASCII choice for one cell, from its 3x7 pooled sub-blocks (bit 3·row + column): `+` for a
// corner, else the glyph of the font whose pooled mask is nearest.
char32_t ascii_glyph_for(unsigned pooled_mask)
{
    if (pooled_mask == 0)
        return U' ';
    if (is_corner(pooled_mask))
        return U'+';
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

} // namespace

char32_t AsciiGlyphCache::glyph_for(unsigned pooled_mask)
{
    const auto found = m_glyphs.find(pooled_mask);
    if (found != m_glyphs.end())
        return found->second;
    const char32_t glyph = ascii_glyph_for(pooled_mask);
    m_glyphs.emplace(pooled_mask, glyph);
    return glyph;
}

CellGrid map_to_cells(const Bitmap& bitmap, CellArea area, GlyphSet glyphs)
{
    AsciiGlyphCache cache;
    return map_to_cells(bitmap, area, glyphs, cache);
}

namespace {

// For each pixel along one axis: the cell it falls in and the bits of the sub-blocks of that cell
// that contain it (the same partition as pool_block, where a sub-block is at least one pixel
// wide, so a pixel can belong to more than one when cells are smaller than the sub-grid).
struct AxisMap {
    std::vector<int> cell;
    std::vector<unsigned> sub_blocks;
};

AxisMap map_axis(int pixels, int cells, int subdivisions)
{
    AxisMap axis{std::vector<int>(static_cast<std::size_t>(pixels)), std::vector<unsigned>(static_cast<std::size_t>(pixels), 0)};
    for (int c = 0; c < cells; ++c) {
        const int start = c * pixels / cells;
        const int end = (c + 1) * pixels / cells;
        const int size = std::max(end - start, 1);
        for (int p = start; p < end; ++p)
            axis.cell[static_cast<std::size_t>(p)] = c;
        for (int sub = 0; sub < subdivisions; ++sub) {
            const int from = std::min(start + sub * size / subdivisions, pixels - 1);
            const int to = std::min(std::max(start + (sub + 1) * size / subdivisions, from + 1), pixels);
            for (int p = from; p < to; ++p)
                if (axis.cell[static_cast<std::size_t>(p)] == c)
                    axis.sub_blocks[static_cast<std::size_t>(p)] |= 1u << sub;
        }
    }
    return axis;
}

// A pooled ASCII cell that is two adjacent full sub-rows and nothing else, as its upper row alone:
// for cell rows of fewer pixels than the 7 sub-rows (5 or 6 at 200x60), where map_axis gives one
// pixel row to two sub-rows, so that a 1-pixel line (the frame's top edge) pools as two bands, the
// font's '=' (its bars 2 pixels apart fall in adjacent sub-rows at 80x24), a double line where the
// screen has one. Cells of 7 pixel rows or more are left as pooled.
unsigned one_line_of_band(unsigned pooled_mask)
{
    constexpr unsigned full_row = (1u << ascii_pool_columns) - 1;
    for (int row = 0; row + 1 < ascii_pool_rows; ++row) {
        const unsigned band = (full_row | (full_row << ascii_pool_columns)) << (row * ascii_pool_columns);
        if (pooled_mask == band)
            return full_row << (row * ascii_pool_columns);
    }
    return pooled_mask;
}

char32_t glyph_of(unsigned mask, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    switch (glyphs) {
    case GlyphSet::braille:
        return braille_glyph(mask);
    case GlyphSet::blocks:
        return quadrant_glyph(mask);
    case GlyphSet::ascii:
    case GlyphSet::automatic:
        break;
    }
    return mask == 0 ? U' ' : cache.glyph_for(mask);
}

} // namespace

CellGrid map_to_cells(const Bitmap& bitmap, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    CellGrid grid(area.columns, area.rows);
    if (area.columns <= 0 || area.rows <= 0 || bitmap.width() <= 0 || bitmap.height() <= 0)
        return grid;
    const int pool_columns = glyphs == GlyphSet::ascii || glyphs == GlyphSet::automatic ? ascii_pool_columns : 2;
    const int pool_rows = glyphs == GlyphSet::ascii || glyphs == GlyphSet::automatic ? ascii_pool_rows
                          : glyphs == GlyphSet::blocks                              ? 2
                                                                                    : 4;
    const AxisMap across = map_axis(bitmap.width(), area.columns, pool_columns);
    const AxisMap down = map_axis(bitmap.height(), area.rows, pool_rows);
    std::vector<unsigned> masks(static_cast<std::size_t>(area.columns) * static_cast<std::size_t>(area.rows), 0);
    // Only lit pixels cost more than a byte test: a path screen has a few thousand of them.
    for (int y = 0; y < bitmap.height(); ++y) {
        const std::uint8_t* row = bitmap.row(y);
        const auto cell_row = static_cast<std::size_t>(down.cell[static_cast<std::size_t>(y)]);
        const unsigned sub_rows = down.sub_blocks[static_cast<std::size_t>(y)];
        for (int byte = 0; byte < (bitmap.width() + 7) / 8; ++byte) {
            if (row[byte] == 0)
                continue;
            for (int bit = 0; bit < 8; ++bit) {
                const int x = byte * 8 + bit;
                if (x >= bitmap.width() || !(row[byte] & (0x80u >> bit)))
                    continue;
                const unsigned sub_columns = across.sub_blocks[static_cast<std::size_t>(x)];
                unsigned& mask = masks[cell_row * static_cast<std::size_t>(area.columns) +
                                       static_cast<std::size_t>(across.cell[static_cast<std::size_t>(x)])];
                for (int sub_row = 0; sub_row < pool_rows; ++sub_row)
                    if (sub_rows & (1u << sub_row))
                        mask |= sub_columns << (sub_row * pool_columns);
            }
        }
    }
    const bool ascii = glyphs == GlyphSet::ascii || glyphs == GlyphSet::automatic;
    for (int row = 0; row < area.rows; ++row) {
        const bool short_row = ascii && (row + 1) * bitmap.height() / area.rows - row * bitmap.height() / area.rows <
                                            ascii_pool_rows;
        for (int column = 0; column < area.columns; ++column) {
            const unsigned mask = masks[static_cast<std::size_t>(row) * static_cast<std::size_t>(area.columns) +
                                        static_cast<std::size_t>(column)];
            grid.set(column, row, glyph_of(short_row ? one_line_of_band(mask) : mask, glyphs, cache));
        }
    }
    return grid;
}

} // namespace apcs
