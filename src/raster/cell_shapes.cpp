#include "cell_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <set>
#include <utility>

namespace apcs {

namespace {

using Cell = std::pair<int, int>; // column, row

Cell cell_of(PixelPoint at, const Bitmap& bitmap, CellArea area)
{
    return {cell_of_pixel(std::clamp(at.x, 0, bitmap.width() - 1), bitmap.width(), area.columns),
            cell_of_pixel(std::clamp(at.y, 0, bitmap.height() - 1), bitmap.height(), area.rows)};
}

// The cells from `from` to `to` by Bresenham's walk, both ends included.
std::vector<Cell> cell_walk(Cell from, Cell to)
{
    std::vector<Cell> cells;
    const int dx = std::abs(to.first - from.first);
    const int dy = -std::abs(to.second - from.second);
    const int step_x = from.first < to.first ? 1 : -1;
    const int step_y = from.second < to.second ? 1 : -1;
    int error = dx + dy;
    for (Cell at = from;;) {
        cells.push_back(at);
        if (at == to)
            return cells;
        const int twice = 2 * error;
        if (twice >= dy) {
            error += dy;
            at.first += step_x;
        }
        if (twice <= dx) {
            error += dx;
            at.second += step_y;
        }
    }
}

// The arrow's direction as seen on a terminal, one of 8 from 0 (right) counterclockwise: a cell
// is about twice as tall as it is wide.
int octant(const CellArrow& arrow, const Bitmap& bitmap, CellArea area)
{
    const double across = static_cast<double>(arrow.tip.x - arrow.tail.x) * area.columns / bitmap.width();
    const double up = -2.0 * static_cast<double>(arrow.tip.y - arrow.tail.y) * area.rows / bitmap.height();
    const double turns = std::atan2(up, across) / (2.0 * std::numbers::pi);
    return (static_cast<int>(std::lround(turns * 8.0)) + 8) % 8;
}

char32_t line_glyph(int direction, LineStyle style, GlyphSet glyphs)
{
    const bool dashed = style != LineStyle::solid;
    if (glyphs == GlyphSet::ascii) {
        static constexpr char32_t lines[] = {U'-', U'/', U'|', U'\\'};
        return lines[direction % 4];
    }
    switch (direction % 4) {
    case 0: return dashed ? U'\u2504' : U'\u2500';
    case 1: return U'\u2571';
    case 2: return dashed ? U'\u2506' : U'\u2502';
    default: return U'\u2572';
    }
}

char32_t head_glyph(int direction, LineStyle style, GlyphSet glyphs)
{
    if (glyphs == GlyphSet::ascii) {
        // ASCII has no slanted arrows: the nearer of right, up, left, down (a slant leans right or left).
        static constexpr char32_t heads[] = {U'>', U'>', U'^', U'<', U'<', U'<', U'v', U'>'};
        return heads[direction];
    }
    // A dashed arrow's head is double (⇒ ⇗ ⇑ …), so that one too short for a gap still reads apart.
    static constexpr char32_t heads[] = {U'\u2192', U'\u2197', U'\u2191', U'\u2196',
                                         U'\u2190', U'\u2199', U'\u2193', U'\u2198'};
    static constexpr char32_t double_heads[] = {U'\u21D2', U'\u21D7', U'\u21D1', U'\u21D6',
                                                U'\u21D0', U'\u21D9', U'\u21D3', U'\u21D8'};
    return style == LineStyle::solid ? heads[direction] : double_heads[direction];
}

// The cells an arrow must leave: those of control points, the local-control arrow and goals.
std::set<Cell> kept_cells(const GraphicsScreen& screen, CellArea area)
{
    std::set<Cell> kept;
    for (const PixelMark& mark : screen.marks) {
        if (mark.kind != MarkKind::control_point && mark.kind != MarkKind::arrow && mark.kind != MarkKind::goal)
            continue;
        Cell cell = cell_of(mark.at, screen.bitmap, area);
        if (mark.kind == MarkKind::arrow)
            cell.first = std::max(cell.first - 1, 0);
        kept.insert(cell);
    }
    return kept;
}

void lay_cell(CellGrid& grid, Cell cell, char32_t glyph, ColourRole role)
{
    grid.set(cell.first, cell.second, glyph);
    grid.set_style(cell.first, cell.second, CellStyle::plain);
    grid.set_role(cell.first, cell.second, role);
}

} // namespace

void lay_cell_arrows(CellGrid& grid, const GraphicsScreen& screen, CellArea area, GlyphSet glyphs)
{
    if (screen.arrows.empty())
        return;
    const std::set<Cell> kept = kept_cells(screen, area);
    for (const CellArrow& arrow : screen.arrows) {
        std::vector<Cell> cells = cell_walk(cell_of(arrow.tail, screen.bitmap, area), cell_of(arrow.tip, screen.bitmap, area));
        std::erase_if(cells, [&](const Cell& cell) { return kept.contains(cell); });
        if (cells.empty())
            continue;
        const int direction = octant(arrow, screen.bitmap, area);
        // Dashed: the cells one step apart from the head backwards, so that the head keeps its shaft.
        for (std::size_t k = 0; k + 1 < cells.size(); ++k)
            if (arrow.style == LineStyle::solid || (cells.size() - 1 - k) % 2 == 0)
                lay_cell(grid, cells[k], line_glyph(direction, arrow.style, glyphs), arrow.role);
        lay_cell(grid, cells.back(), head_glyph(direction, arrow.style, glyphs), arrow.role);
    }
}

void lay_cell_boxes(CellGrid& grid, const GraphicsScreen& screen, CellArea area, GlyphSet glyphs)
{
    const bool ascii = glyphs == GlyphSet::ascii;
    const char32_t across = ascii ? U'-' : U'\u2500';
    const char32_t upright = ascii ? U'|' : U'\u2502';
    for (const PixelRect& box : screen.boxes) {
        const Cell first = cell_of({box.left, box.top}, screen.bitmap, area);
        const Cell last = cell_of({box.right, box.bottom}, screen.bitmap, area);
        const auto [left, top] = first;
        const auto [right, bottom] = last;
        if (right <= left || bottom <= top)
            continue;
        for (int column = left + 1; column < right; ++column)
            for (const int row : {top, bottom})
                lay_cell(grid, {column, row}, across, ColourRole::region);
        for (int row = top + 1; row < bottom; ++row)
            for (const int column : {left, right})
                lay_cell(grid, {column, row}, upright, ColourRole::region);
        lay_cell(grid, {left, top}, ascii ? U'+' : U'\u250C', ColourRole::region);
        lay_cell(grid, {right, top}, ascii ? U'+' : U'\u2510', ColourRole::region);
        lay_cell(grid, {left, bottom}, ascii ? U'+' : U'\u2514', ColourRole::region);
        lay_cell(grid, {right, bottom}, ascii ? U'+' : U'\u2518', ColourRole::region);
    }
}

} // namespace apcs
