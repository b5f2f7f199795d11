#include "apcs/raster/graphics_screen.h"

#include "apcs/raster/font.h"
#include "apcs/raster/painter.h"

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
            grid.set(mark.at.x * area.columns / screen.bitmap.width(), mark.at.y * area.rows / screen.bitmap.height(),
                     mark.glyph);
    for (const TextLine& line : screen.text) {
        const int column = line.column * area.columns / text_screen_columns;
        const int row = line.row * area.rows / text_screen_rows;
        // Text replaces the raster glyphs of the cells it covers.
        grid.put_text(column, row, line.text);
    }
    return grid;
}

} // namespace apcs
