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
    ColourRole role = ColourRole::monitor;
    bool operator==(const TextLine&) const = default;
};

// What a mark stands for. Marks are kept apart from the raster's lines so that at any terminal size
// each is one readable character (SPEC §7.2), while pictures draw their pixel shapes.
enum class MarkKind {
    control_point, // `x`; pixels: an x of 5x5 (thesis Pre_Draw)
    inbetween,     // `*` in ascii, `•` elsewhere; pixels: a 3x3 square (Draw_Ani_Path)
    arrow,         // `>` in ascii, `→` elsewhere, in the cell left of `at`; pixels: an arrow
    staff_value,   // `O`; pixels: two short vertical lines around the value
    tangent_end,   // `+`: the free end of a tangent arrow (the handle); pixels: a plus of 5x5
    goal,          // `@`: an exercise's goal point (GOAL NEAR, INBETWEEN); pixels: a diamond of 11x11
};

// A mark at a raster pixel. A reverse-styled control point is one of the picked region: reverse
// video in a terminal, a box around it in a picture.
struct PixelMark {
    PixelPoint at;
    MarkKind kind = MarkKind::control_point;
    CellStyle style = CellStyle::plain;
    ColourRole role = ColourRole::monitor;
    bool operator==(const PixelMark&) const = default;
};

// A horizontal line with upright ticks: a line of the four-line staff (fig. 3.1.5), in raster
// pixels. Kept apart from the raster, as the marks are, so that at any terminal size it is one row of
// characters in the cell row its `y` falls in (the row of the label beside it, whose text row has
// its middle there): drawn into the raster, a tick taller than a cell row spilled into the rows
// around it, and the line's place within its cell row chose the glyph (`_` in one row, `-` in the
// next). Pictures draw its pixels.
struct TickedLine {
    int left = 0;  // the first pixel of the line
    int right = 0; // the last
    int y = 0;
    std::vector<int> ticks;   // each tick's x, in [left, right]
    int tick_half_height = 0; // a tick runs from y − this to y + this
    bool operator==(const TickedLine&) const = default;
};

// A tangent arrow of the path screen (T), from `tail` to `tip` in raster pixels. Pictures draw its
// pixels into the raster; a terminal lays it as characters at any size, so that without colour it
// still reads apart from the curve and from the other style: in each cell from tail to tip the
// line's glyph for its direction (solid: every cell; dashed: every other), and an arrowhead
// pointing its way in the last cell that holds no control point.
struct CellArrow {
    PixelPoint tail;
    PixelPoint tip;
    LineStyle style = LineStyle::solid;
    ColourRole role = ColourRole::tangent;
    bool operator==(const CellArrow&) const = default;
};

// What graphics mode shows: the 720x348 raster of lines, the ticked lines, the marks and the text
// over it. `strokes` holds the raster's lines as vector lines where the drawing recorded them
// (Painter::record_into), for pictures that scale (SVG).
struct GraphicsScreen {
    Bitmap bitmap;
    std::vector<TickedLine> ticked_lines;
    std::vector<TextLine> text;
    std::vector<PixelMark> marks;
    std::vector<Stroke> strokes;
    // Tangent arrows: their pixels are in the raster too (pictures), under the role `role`;
    // render_cells lays them as characters instead.
    std::vector<CellArrow> arrows;
    // Boxes a terminal draws in line characters on the cells each rectangle's edges fall in (the
    // picked region, SPEC §7.2); pictures box each point instead.
    std::vector<PixelRect> boxes;
    // The colour role of each raster pixel (row by row), empty while every lit pixel is the
    // monitor's; paint_layer fills it. Pictures ignore it (SPEC §7.1: the monitor had one colour).
    std::vector<ColourRole> pixel_roles;
    bool operator==(const GraphicsScreen&) const = default;
};

// Lights the pixels `layer` lights, in `role`: a pixel lit before keeps the role of higher
// colour_priority, so the order layers are painted in does not change what a cell shows.
void paint_layer(GraphicsScreen& screen, const Bitmap& layer, ColourRole role);
// The role pixel (x, y) was painted in (monitor where none was given).
ColourRole pixel_role(const GraphicsScreen& screen, int x, int y);

// The character a mark shows in `glyphs`.
char32_t mark_glyph(MarkKind kind, GlyphSet glyphs);

// The characters a ticked line is laid in, in one glyph set: the same whatever the terminal's size.
struct TickedLineGlyphs {
    char32_t line;     // a cell the line runs through
    char32_t first;    // the tick where the line starts
    char32_t crossing; // a tick the line runs on through
    char32_t last;     // the tick where it ends
};
TickedLineGlyphs ticked_line_glyphs(GlyphSet glyphs);

// A ticked line as the strokes a Painter draws it with (the line, then each tick), unclipped.
std::vector<Stroke> ticked_line_strokes(const TickedLine& line);

// The raster with its ticked lines, its marks' pixel shapes and its text drawn in the 9x14 font, as
// the Hercules card showed it (for PNG).
Bitmap render_raster(const GraphicsScreen& screen);

// The raster mapped to characters, then the ticked lines, the marks and the text laid over it as
// real characters, each at its share of the area (80x24 text cells scale with the area). Marks take the cell their
// pixel falls in, control points before the others; two or more in-betweens in one cell show their
// count (2 … 9). A raster cell's colour role is the highest colour_priority of its lit pixels'; a
// mark or text cell has the mark's or the text's. The 80x23 short screen lays the screen out anew
// first (screens/short_screen.h: render_screen_cells).
CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs);
CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache);

} // namespace apcs
