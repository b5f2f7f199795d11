#include "apcs/terminal/terminal_pixels.h"

#include "apcs/geometry/hercules.h"
#include "apcs/raster/terminal_picture.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/short_screen.h"

#include <algorithm>
#include <utility>

namespace apcs {

namespace {

// The raster as pictures show it (render_raster), dark below the drawing area's boundary: where the
// terminal's cell rows do not end with the boundary (100x30: cell row 22 holds raster rows 255-266),
// the picture's last row would show the top of the message row's text, which curses shows below.
Bitmap drawing_area_raster(const GraphicsScreen& screen)
{
    Bitmap raster = render_raster(screen);
    for (int y = layout::drawing_area.bottom + 1; y < raster.height(); ++y)
        for (int x = 0; x < raster.width(); ++x)
            raster.set(x, y, false);
    return raster;
}

} // namespace

TerminalPixels::TerminalPixels(TerminalDevice& terminal, PixelDecision decision)
    : m_terminal(terminal), m_protocol(decision.protocol), m_notice(std::move(decision.why_not))
{
}

std::optional<PictureFrame> TerminalPixels::frame_for(TerminalSize size) const
{
    const std::optional<CellArea> area = fit_cell_area(size.columns, size.rows);
    if (!m_protocol || !area)
        return std::nullopt;
    const std::optional<CellPixels> cell = m_terminal.cell_pixels();
    if (!cell)
        return std::nullopt;
    // The cell rows of the drawing area and its boundary (text rows 0-17 at 80x24, shown in 17 on the
    // short screen), and the raster rows they show: on the short screen the picture keeps the
    // raster's proportions in its 17 rows, narrower than the characters' squeeze.
    const bool short_area = is_short_area(*area);
    const int rows = short_area ? layout::message_row - 1
                                : cell_rows_above(layout::drawing_area.bottom + 1, hercules::screen_height, *area);
    const int raster_rows =
        short_area ? hercules::text_row_top(layout::message_row) : rows * hercules::screen_height / area->rows;
    // xterm shows no sixel picture beyond its limit (1000x1000, and its window): not a smaller one.
    const std::optional<PictureLimit> limit =
        *m_protocol == TerminalPictureProtocol::sixel ? m_terminal.sixel_limit() : std::nullopt;
    const std::optional<PicturePlacement> placement =
        place_picture(*area, rows, hercules::screen_width, raster_rows, *cell, limit);
    if (!placement)
        return std::nullopt;
    return PictureFrame{*placement, rows};
}

void TerminalPixels::before_show(const std::optional<PictureFrame>& frame)
{
    // A picture stays where the next one covers it; one at another place or size (a resize) would
    // leave its pixels beside the new one, where curses believes blank cells are.
    if (!m_sent_placement || (frame && frame->placement == *m_sent_placement))
        return;
    if (m_protocol)
        m_terminal.remove_pictures(*m_protocol);
    m_terminal.redraw();
    m_sent_placement.reset();
}

void TerminalPixels::show(const GraphicsScreen& screen, const PictureFrame& frame, bool repainted)
{
    if (!m_protocol)
        return;
    const PicturePlacement& placement = frame.placement;
    const Bitmap picture = scale_to_picture(drawing_area_raster(screen), placement);
    const bool whole = repainted || m_sent_placement != placement || m_bands_since_whole >= most_bands;
    const std::optional<CellRowBand> band =
        whole ? CellRowBand{0, placement.rows} : changed_band(m_sent, picture, placement.cell.height);
    if (!band)
        return;
    const Expected<std::string> sequences = encode_picture_band(picture, *band, placement.cell, *m_protocol);
    if (!sequences) {
        // Characters from now on: the next screen repaints every cell over what was sent.
        m_notice = std::string(encoding_failed_line) + " (" + sequences.error().message + ")";
        m_terminal.remove_pictures(*m_protocol);
        m_protocol.reset();
        m_sent_placement.reset();
        m_terminal.redraw();
        return;
    }
    // A whole kitty picture replaces the pictures before it, which kitty would keep beneath.
    if (whole && m_sent_placement)
        m_terminal.remove_pictures(*m_protocol);
    m_terminal.send_picture(placement.column, band->first, *sequences);
    m_bands_since_whole = whole ? 0 : m_bands_since_whole + 1;
    m_sent = picture;
    m_sent_placement = placement;
}

CellGrid without_rows(CellGrid grid, int rows)
{
    for (int row = 0; row < std::min(rows, grid.rows()); ++row)
        for (int column = 0; column < grid.columns(); ++column) {
            grid.set(column, row, U' ');
            grid.set_style(column, row, CellStyle::plain);
            grid.set_role(column, row, ColourRole::monitor);
        }
    return grid;
}

} // namespace apcs
