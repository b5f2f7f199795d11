#include "apcs/raster/graphics_screen.h"

#include "apcs/raster/font.h"
#include "apcs/raster/painter.h"

#include <algorithm>

namespace apcs {

Bitmap render_raster(const GraphicsScreen& screen)
{
    Bitmap raster = screen.bitmap;
    Painter painter(raster);
    for (const TextLine& line : screen.text)
        painter.text({line.column * Font::cell_width, line.row * Font::cell_height}, line.text);
    return raster;
}

CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs)
{
    AsciiGlyphCache cache;
    return render_cells(screen, area, glyphs, cache);
}

CellGrid render_cells(const GraphicsScreen& screen, CellArea area, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    CellGrid grid = map_to_cells(screen.bitmap, area, glyphs, cache);
    for (const PixelMark& mark : screen.marks)
        if (screen.bitmap.contains(mark.at.x, mark.at.y))
            grid.set(cell_of_pixel(mark.at.x, screen.bitmap.width(), area.columns),
                     cell_of_pixel(mark.at.y, screen.bitmap.height(), area.rows), mark.glyph);
    for (const TextLine& line : screen.text) {
        // A text cell goes where the centre of its 9x14 pixels falls, so that text lines up with
        // what the raster draws beside it (a staff line and its label) at any area size.
        const int centre_x = line.column * Font::cell_width + Font::cell_width / 2;
        const int centre_y = line.row * Font::cell_height + Font::cell_height / 2;
        const int column = cell_of_pixel(centre_x, screen.bitmap.width(), area.columns);
        const int row = std::min(cell_of_pixel(centre_y, screen.bitmap.height(), area.rows), area.rows - 1);
        // Text replaces the raster glyphs of the cells it covers.
        grid.put_text(column, row, line.text);
    }
    return grid;
}

} // namespace apcs
