#pragma once

#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/graphics_screen.h"

namespace apcs {

// The screen on a terminal one row short of 80x24: 80x23, the pane tmux or screen leaves under its
// status line on an 80x24 window, where classes share a session. The drawing area gives up a cell
// row (its text rows 0-17 are shown in 17) and every text row from the message on moves up one, so
// the message, the four-line staff and the key-hint or caption row all stay.

// Whether `area` (fit_cell_area's) is the short screen.
constexpr bool is_short_area(CellArea area) { return area.rows == short_screen_rows; }

// Where the short screen puts raster row `y` of the 720x348 screen, in the 24 text rows' raster:
// the drawing area's rows squeezed into the top 17 text rows (its top row kept, the boundary's),
// each text row below it one text row up; the last text row's raster rows stay empty.
int short_screen_y(int y);

// `screen` laid out for the short screen in the 24 text rows' raster (short_screen_y): lit pixels,
// their colour roles, marks and ticked lines moved; text rows from the message on one row up, a
// text row of the drawing area to the row its middle falls in. render_cells shows its first 23 rows.
GraphicsScreen on_short_screen(const GraphicsScreen& screen);

// An 80x24 text screen (the console, a help screen) on the short screen: its first blank row left
// out, or where none is blank its top row, the oldest line of a console (as if it had scrolled).
CellGrid text_on_short_screen(const CellGrid& text);

// `grid` without row `row`: the rows below it move up one.
CellGrid without_row(const CellGrid& grid, int row);

// What a terminal shows of `screen` in `area` (fit_cell_area's): render_cells, or on the short
// screen its layout (on_short_screen) in 23 of the 24 text rows.
CellGrid render_screen_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache);
CellGrid render_screen_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs);

} // namespace apcs
