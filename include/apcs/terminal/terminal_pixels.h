#pragma once

#include "apcs/raster/graphics_screen.h"
#include "apcs/raster/pixel_picture.h"
#include "apcs/terminal/pixel_detection.h"
#include "apcs/terminal/terminal_device.h"

#include <optional>
#include <string>

namespace apcs {

// A graphics screen's drawing area as a picture on a terminal of some size: where the picture goes,
// and the cell rows (from the top) that curses leaves blank under it.
struct PictureFrame {
    PicturePlacement placement;
    int blank_rows = 0;
};

// The drawing area of the graphics screens as a picture (--pixels, SPEC §7.2.1), sent through a
// TerminalDevice (which it does not own and which outlives it) after curses has drawn the characters
// around it: the whole picture after anything that repainted the terminal, else only the band of
// cell rows that changed. Falls back to characters for good when the picture cannot be encoded.
class TerminalPixels {
public:
    TerminalPixels(TerminalDevice& terminal, PixelDecision decision);

    // The picture's place on a terminal of `size` for a graphics screen; nullopt where the screen
    // stays characters (pixels off, the terminal below 80x24, no cell size in pixels).
    std::optional<PictureFrame> frame_for(TerminalSize size) const;
    // Before curses shows a screen: one without a picture (`frame` nullopt), or with a picture at
    // another place or size, where a picture is on the terminal takes it off first, and has the
    // terminal clear and repaint every cell.
    void before_show(const std::optional<PictureFrame>& frame);
    // After curses showed `screen` with `frame`'s rows blank (`repainted`: every cell was sent,
    // TerminalDevice::show): sends the picture, whole or its changed band.
    void show(const GraphicsScreen& screen, const PictureFrame& frame, bool repainted);
    // Why pictures are off, until a key is typed (clear_notice): one line for the message line;
    // empty when they are on or were not asked for.
    const std::string& notice() const { return m_notice; }
    void clear_notice() { m_notice.clear(); }

private:
    TerminalDevice& m_terminal;
    std::optional<TerminalPictureProtocol> m_protocol;
    std::string m_notice;
    // What is on the terminal: the picture last sent (whole or in bands) and its placement;
    // nullopt when none is.
    std::optional<PicturePlacement> m_sent_placement;
    Bitmap m_sent;
    // Bands sent since the last whole picture: xterm keeps 16 sixel pictures at most and recycles
    // the oldest (the whole one beneath the bands), kitty keeps every band as an image until the
    // next whole picture removes them; so a whole picture goes again after most_bands of them.
    int m_bands_since_whole = 0;
    static constexpr int most_bands = 12;
};

// `grid` with rows 0 … rows − 1 blank: the cells under a picture, which curses must not paint.
CellGrid without_rows(CellGrid grid, int rows);

} // namespace apcs
