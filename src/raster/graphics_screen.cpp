#include "apcs/raster/graphics_screen.h"

#include "cell_shapes.h"
#include "apcs/raster/font.h"
#include "apcs/raster/painter.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

namespace apcs {

char32_t mark_glyph(MarkKind kind, GlyphSet glyphs)
{
    const bool ascii = glyphs == GlyphSet::ascii;
    switch (kind) {
    case MarkKind::control_point: return U'x';
    case MarkKind::inbetween: return ascii ? U'*' : U'\u2022';
    case MarkKind::arrow: return ascii ? U'>' : U'\u2192';
    case MarkKind::staff_value: return U'O';
    case MarkKind::tangent_end: return U'+';
    case MarkKind::goal: return U'@';
    }
    return U'?';
}

TickedLineGlyphs ticked_line_glyphs(GlyphSet glyphs)
{
    switch (glyphs) {
    case GlyphSet::braille:
        // A line of dots 3 and 6; a tick two dots tall beside it, as the staff's ticks (7 pixels
        // of a 14.5-pixel row) were pooled at 80x24.
        return {U'\u2824', U'\u2826', U'\u2834', U'\u2806'};
    case GlyphSet::blocks:
        // Quadrants are half a cell tall, a heavy bar for a 1-pixel line: the light box-drawing
        // characters (code page 437 had them) draw it as thin as braille's dots.
        return {U'\u2500', U'\u251C', U'\u253C', U'\u2524'};
    case GlyphSet::ascii:
    case GlyphSet::automatic:
        break;
    }
    return {U'-', U'|', U'+', U'|'};
}

std::vector<Stroke> ticked_line_strokes(const TickedLine& line)
{
    std::vector<Stroke> strokes{{{{line.left, line.y}, {line.right, line.y}}, LineStyle::solid, std::nullopt}};
    for (const int x : line.ticks)
        strokes.push_back({{{x, line.y - line.tick_half_height}, {x, line.y + line.tick_half_height}},
                           LineStyle::solid, std::nullopt});
    return strokes;
}

namespace {

// Half the height of the staff's value marker, in pixels.
constexpr int staff_marker_half_height = 4;

void draw_mark_pixels(Painter& painter, const PixelMark& mark)
{
    const PixelPoint at = mark.at;
    switch (mark.kind) {
    case MarkKind::control_point:
        painter.cross_marker(at);
        if (mark.style == CellStyle::reverse)
            painter.rectangle({at.x - 4, at.y - 4, at.x + 5, at.y + 5});
        return;
    case MarkKind::inbetween:
        painter.dot_marker(at);
        return;
    case MarkKind::arrow:
        // Pointing right at `at` from the left, as the character stands left of its point.
        painter.line({at.x - 16, at.y}, {at.x - 5, at.y});
        painter.line({at.x - 8, at.y - 3}, {at.x - 5, at.y});
        painter.line({at.x - 8, at.y + 3}, {at.x - 5, at.y});
        return;
    case MarkKind::staff_value:
        for (const int side : {-1, 1})
            painter.line({at.x + side, at.y - staff_marker_half_height}, {at.x + side, at.y + staff_marker_half_height});
        return;
    case MarkKind::tangent_end:
        painter.line({at.x - 2, at.y}, {at.x + 2, at.y});
        painter.line({at.x, at.y - 2}, {at.x, at.y + 2});
        return;
    case MarkKind::goal:
        painter.line({at.x - 5, at.y}, {at.x, at.y - 5});
        painter.line({at.x, at.y - 5}, {at.x + 5, at.y});
        painter.line({at.x + 5, at.y}, {at.x, at.y + 5});
        painter.line({at.x, at.y + 5}, {at.x - 5, at.y});
        painter.dot_marker(at);
        return;
    }
}

// The order marks are laid over the cells: a later kind hides an earlier one in the same cell.
constexpr int top_mark_layer = 5;
int mark_layer(MarkKind kind)
{
    switch (kind) {
    case MarkKind::inbetween: return 0;
    case MarkKind::tangent_end: return 1;
    case MarkKind::staff_value: return 2;
    case MarkKind::arrow: return 3;
    case MarkKind::control_point: return 4;
    case MarkKind::goal: return top_mark_layer;
    }
    return 0;
}

void lay_marks(CellGrid& grid, const GraphicsScreen& screen, CellArea area, GlyphSet glyphs)
{
    std::map<std::pair<int, int>, int> inbetweens_in_cell;
    for (int layer = 0; layer <= top_mark_layer; ++layer)
        for (const PixelMark& mark : screen.marks) {
            if (mark_layer(mark.kind) != layer || !screen.bitmap.contains(mark.at.x, mark.at.y))
                continue;
            // Where arrows are laid as characters their heads stand for the free ends.
            if (mark.kind == MarkKind::tangent_end && !screen.arrows.empty())
                continue;
            int column = cell_of_pixel(mark.at.x, screen.bitmap.width(), area.columns);
            const int row = cell_of_pixel(mark.at.y, screen.bitmap.height(), area.rows);
            if (mark.kind == MarkKind::arrow)
                column = std::max(column - 1, 0);
            char32_t glyph = mark_glyph(mark.kind, glyphs);
            if (mark.kind == MarkKind::inbetween) {
                const int count = ++inbetweens_in_cell[{column, row}];
                if (count > 1)
                    glyph = U'0' + static_cast<char32_t>(std::min(count, 9));
            }
            grid.set(column, row, glyph);
            grid.set_style(column, row, mark.style);
            grid.set_role(column, row, mark.role);
        }
}

// Each ticked line as one row of characters: the line's glyph from its first cell to its last, a
// tick's glyph in the cell its pixel falls in.
void lay_ticked_lines(CellGrid& grid, const GraphicsScreen& screen, CellArea area, GlyphSet glyphs)
{
    const TickedLineGlyphs shown = ticked_line_glyphs(glyphs);
    const int width = screen.bitmap.width();
    for (const TickedLine& line : screen.ticked_lines) {
        if (line.y < 0 || line.y >= screen.bitmap.height())
            continue;
        const int row = cell_of_pixel(line.y, screen.bitmap.height(), area.rows);
        const int first = cell_of_pixel(std::clamp(line.left, 0, width - 1), width, area.columns);
        const int last = cell_of_pixel(std::clamp(line.right, 0, width - 1), width, area.columns);
        for (int column = first; column <= last; ++column)
            grid.set(column, row, shown.line);
        for (const int x : line.ticks) {
            const int column = cell_of_pixel(std::clamp(x, 0, width - 1), width, area.columns);
            grid.set(column, row, column == first ? shown.first : column == last ? shown.last : shown.crossing);
        }
    }
}

std::size_t pixel_index(const Bitmap& bitmap, int x, int y)
{
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(bitmap.width()) + static_cast<std::size_t>(x);
}

// The raster a terminal maps to cells: without the arrows' pixels where arrows are laid as
// characters, or their dots would blur the characters' cells' neighbours.
Bitmap raster_for_cells(const GraphicsScreen& screen)
{
    Bitmap raster = screen.bitmap;
    if (screen.arrows.empty() || screen.pixel_roles.empty())
        return raster;
    for (int y = 0; y < raster.height(); ++y)
        for (int x = 0; x < raster.width(); ++x)
            if (screen.pixel_roles[pixel_index(raster, x, y)] == ColourRole::tangent)
                raster.set(x, y, false);
    return raster;
}

// Each cell of the raster in the role of its lit pixel of highest priority.
void lay_pixel_roles(CellGrid& grid, const GraphicsScreen& screen, CellArea area)
{
    if (screen.pixel_roles.empty())
        return;
    const Bitmap& bitmap = screen.bitmap;
    for (int y = 0; y < bitmap.height(); ++y) {
        const int row = cell_of_pixel(y, bitmap.height(), area.rows);
        for (int x = 0; x < bitmap.width(); ++x) {
            if (!bitmap.get(x, y))
                continue;
            const int column = cell_of_pixel(x, bitmap.width(), area.columns);
            const ColourRole role = screen.pixel_roles[pixel_index(bitmap, x, y)];
            if (colour_priority(role) > colour_priority(grid.role_at(column, row)))
                grid.set_role(column, row, role);
        }
    }
}

// Raster cells default to monitor, whose priority is above the ghost's and the key frames': a cell
// of ghost pixels only must start below them.
void lay_roles_under_marks(CellGrid& grid, const GraphicsScreen& screen, CellArea area)
{
    if (screen.pixel_roles.empty())
        return;
    for (int row = 0; row < grid.rows(); ++row)
        for (int column = 0; column < grid.columns(); ++column)
            grid.set_role(column, row, ColourRole::key_frame);
    lay_pixel_roles(grid, screen, area);
    for (int row = 0; row < grid.rows(); ++row)
        for (int column = 0; column < grid.columns(); ++column)
            if (grid.at(column, row) == U' ' || grid.at(column, row) == U'\u2800')
                grid.set_role(column, row, ColourRole::monitor);
}

} // namespace

void paint_layer(GraphicsScreen& screen, const Bitmap& layer, ColourRole role)
{
    Bitmap& bitmap = screen.bitmap;
    if (screen.pixel_roles.empty() && role == ColourRole::monitor) {
        bitmap.merge(layer);
        return;
    }
    if (screen.pixel_roles.empty())
        screen.pixel_roles.assign(static_cast<std::size_t>(bitmap.width()) * static_cast<std::size_t>(bitmap.height()),
                                  ColourRole::monitor);
    // A layer is mostly unlit: its rows are read a byte (8 pixels) at a time.
    const int width = std::min(bitmap.width(), layer.width());
    for (int y = 0; y < std::min(bitmap.height(), layer.height()); ++y) {
        const std::uint8_t* row = layer.row(y);
        for (int first = 0; first < width; first += 8) {
            const std::uint8_t lit = row[first / 8];
            if (lit == 0)
                continue;
            for (int x = first; x < std::min(width, first + 8); ++x) {
                if ((lit & (0x80u >> (x - first))) == 0) // most significant bit leftmost, as Bitmap::set
                    continue;
                ColourRole& shown = screen.pixel_roles[pixel_index(bitmap, x, y)];
                if (!bitmap.get(x, y) || colour_priority(role) > colour_priority(shown))
                    shown = role;
                bitmap.set(x, y, true);
            }
        }
    }
}

ColourRole pixel_role(const GraphicsScreen& screen, int x, int y)
{
    if (screen.pixel_roles.empty() || !screen.bitmap.contains(x, y))
        return ColourRole::monitor;
    return screen.pixel_roles[pixel_index(screen.bitmap, x, y)];
}

Bitmap render_raster(const GraphicsScreen& screen)
{
    Bitmap raster = screen.bitmap;
    Painter painter(raster);
    for (const TickedLine& line : screen.ticked_lines)
        for (const Stroke& stroke : ticked_line_strokes(line))
            painter.line(stroke.points.front(), stroke.points.back());
    for (const PixelMark& mark : screen.marks)
        draw_mark_pixels(painter, mark);
    for (const TextLine& line : screen.text)
        painter.text({line.column * Font::cell_width, hercules::text_row_top(line.row)}, line.text);
    return raster;
}

CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs)
{
    AsciiGlyphCache cache;
    return render_cells(screen, area, glyphs, cache);
}

CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    CellGrid grid = screen.arrows.empty() ? map_to_cells(screen.bitmap, area, glyphs, cache)
                                          : map_to_cells(raster_for_cells(screen), area, glyphs, cache);
    lay_roles_under_marks(grid, screen, area);
    lay_ticked_lines(grid, screen, area, glyphs);
    lay_cell_boxes(grid, screen, area, glyphs);
    lay_marks(grid, screen, area, glyphs);
    lay_cell_arrows(grid, screen, area, glyphs);
    for (const TextLine& line : screen.text) {
        // A text cell goes where the centre of its 9x14 pixels falls, so that text lines up with
        // what the raster draws beside it (a staff line and its label) at any area size.
        const int centre_x = line.column * Font::cell_width + Font::cell_width / 2;
        const int centre_y = hercules::text_row_top(line.row) + Font::cell_height / 2;
        const int column = cell_of_pixel(centre_x, screen.bitmap.width(), area.columns);
        const int row = std::min(cell_of_pixel(centre_y, screen.bitmap.height(), area.rows), area.rows - 1);
        // Text replaces the raster glyphs of the cells it covers.
        grid.put_text(column, row, line.text, line.style, line.role);
    }
    return grid;
}

} // namespace apcs
