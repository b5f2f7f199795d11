#pragma once

#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/graphics_screen.h"

namespace apcs {

// The shapes a terminal draws in characters over the mapped raster, so that they read at any size
// and without colour (SPEC §7.2, §7.2.1): tangent arrows and the boxes around the picked region.

// Lays each of the screen's arrows: its line's glyph for its direction from its tail's cell to its
// tip's (solid in every cell, dashed in every other, skipping cells that hold a control point, the
// local-control arrow or a goal), and an arrowhead in the last such cell. ASCII: - | / \ and the
// heads > < ^ v; the other sets: box-drawing lines (dashed ┄ ┆) and the arrows → ↗ ↑ … (dashed:
// the double arrows ⇒ ⇗ ⇑ …).
void lay_cell_arrows(CellGrid& grid, const GraphicsScreen& screen, CellArea area, GlyphSet glyphs);

// Lays each of the screen's boxes on the cells its rectangle's edges fall in, in line characters
// (ASCII + - |, else ┌ ─ ┐ │ └ ┘); marks laid after it keep their cells.
void lay_cell_boxes(CellGrid& grid, const GraphicsScreen& screen, CellArea area, GlyphSet glyphs);

} // namespace apcs
