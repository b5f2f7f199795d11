#include "apcs/screens/short_screen.h"

#include "apcs/geometry/hercules.h"
#include "apcs/raster/screen_layout.h"

#include <algorithm>
#include <cstdint>

namespace apcs {

namespace {

using hercules::text_row_top;

// The drawing area's text rows (0-17) and the raster rows they cover, on 80x24 and on the short
// screen. Its top row, the boundary above the view's margin of one cell, stays as it is; the rows
// below it are squeezed into one row fewer, so a point on the view's edge stays off the boundary.
constexpr int kept_raster_rows = text_row_top(1);
constexpr int drawing_raster_rows = text_row_top(layout::message_row);
constexpr int short_drawing_raster_rows = text_row_top(layout::message_row - 1);

std::size_t pixel_index(int width, int x, int y)
{
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
}

// Each lit pixel of `screen` at its row on the short screen into `moved`, its colour role (where
// the screen has roles) the higher colour_priority of those that land on one pixel.
void move_pixels(const GraphicsScreen& screen, GraphicsScreen& moved)
{
    const Bitmap& from = screen.bitmap;
    const bool roles = !screen.pixel_roles.empty();
    if (roles)
        moved.pixel_roles.assign(screen.pixel_roles.size(), ColourRole::monitor);
    for (int y = 0; y < from.height(); ++y) {
        const std::uint8_t* row = from.row(y);
        const int to_y = short_screen_y(y);
        for (int byte = 0; byte < (from.width() + 7) / 8; ++byte) {
            if (row[byte] == 0)
                continue;
            for (int x = byte * 8; x < std::min(byte * 8 + 8, from.width()); ++x) {
                if (!from.get(x, y))
                    continue;
                if (roles) {
                    const ColourRole role = screen.pixel_roles[pixel_index(from.width(), x, y)];
                    ColourRole& shown = moved.pixel_roles[pixel_index(from.width(), x, to_y)];
                    if (!moved.bitmap.get(x, to_y) || colour_priority(role) > colour_priority(shown))
                        shown = role;
                }
                moved.bitmap.set(x, to_y, true);
            }
        }
    }
}

// The text row line `row` is shown in on the short screen.
int short_text_row(int row)
{
    if (row >= layout::message_row)
        return row - 1;
    const int middle = short_screen_y(text_row_top(row) + hercules::cell_height / 2);
    return cell_of_pixel(middle, hercules::screen_height, text_screen_rows);
}

bool blank_row(const CellGrid& grid, int row)
{
    for (int column = 0; column < grid.columns(); ++column)
        if (grid.at(column, row) != U' ' || grid.style_at(column, row) != CellStyle::plain ||
            !grid.marks_at(column, row).empty())
            return false;
    return true;
}

} // namespace

int short_screen_y(int y)
{
    if (y < kept_raster_rows)
        return y;
    if (y < drawing_raster_rows)
        return kept_raster_rows + (y - kept_raster_rows) * (short_drawing_raster_rows - kept_raster_rows) /
                                      (drawing_raster_rows - kept_raster_rows);
    int row = layout::message_row;
    while (row + 1 < text_screen_rows && text_row_top(row + 1) <= y)
        ++row;
    // Text rows are 14 or 15 raster rows: a 15th row lands on the 14th of a 14-row one.
    return std::min(text_row_top(row - 1) + (y - text_row_top(row)), text_row_top(row) - 1);
}

GraphicsScreen on_short_screen(const GraphicsScreen& screen)
{
    GraphicsScreen moved;
    moved.bitmap = Bitmap(screen.bitmap.width(), screen.bitmap.height());
    move_pixels(screen, moved);
    moved.strokes = screen.strokes;
    moved.ticked_lines = screen.ticked_lines;
    for (TickedLine& line : moved.ticked_lines)
        line.y = short_screen_y(line.y);
    moved.marks = screen.marks;
    for (PixelMark& mark : moved.marks)
        mark.at.y = short_screen_y(mark.at.y);
    moved.arrows = screen.arrows;
    for (CellArrow& arrow : moved.arrows) {
        arrow.tail.y = short_screen_y(arrow.tail.y);
        arrow.tip.y = short_screen_y(arrow.tip.y);
    }
    moved.boxes = screen.boxes;
    for (PixelRect& box : moved.boxes) {
        box.top = short_screen_y(box.top);
        box.bottom = short_screen_y(box.bottom);
    }
    moved.text = screen.text;
    for (TextLine& line : moved.text)
        line.row = short_text_row(line.row);
    return moved;
}

CellGrid text_on_short_screen(const CellGrid& text)
{
    for (int row = 0; row < text.rows(); ++row)
        if (blank_row(text, row))
            return without_row(text, row);
    return without_row(text, 0);
}

CellGrid without_row(const CellGrid& grid, int row)
{
    CellGrid kept(grid.columns(), std::max(grid.rows() - 1, 0));
    for (int to = 0; to < kept.rows(); ++to) {
        const int from = to < row ? to : to + 1;
        for (int column = 0; column < grid.columns(); ++column) {
            kept.set(column, to, grid.at(column, from));
            for (const char32_t mark : grid.marks_at(column, from))
                kept.add_mark(column, to, mark);
            kept.set_style(column, to, grid.style_at(column, from));
            kept.set_role(column, to, grid.role_at(column, from));
        }
    }
    return kept;
}

CellGrid render_screen_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    // The short screen's layout fills 23 of the 24 text rows: the 24th is left out.
    if (is_short_area(area))
        return without_row(render_cells(on_short_screen(screen), {area.columns, text_screen_rows}, glyphs, cache),
                           text_screen_rows - 1);
    return render_cells(screen, area, glyphs, cache);
}

CellGrid render_screen_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs)
{
    AsciiGlyphCache cache;
    return render_screen_cells(screen, area, glyphs, cache);
}

} // namespace apcs
