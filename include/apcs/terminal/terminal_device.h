#pragma once

#include "apcs/formats/key_event.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/pixel_picture.h"
#include "apcs/terminal/pixel_detection.h"

#include <chrono>
#include <optional>
#include <string_view>

namespace apcs {

struct TerminalSize {
    int columns = 0;
    int rows = 0;
    bool operator==(const TerminalSize&) const = default;
};

// What read_key saw: a key, nothing within the time-out, a resize, or a request to stop
// (SIGINT, SIGTERM, SIGHUP, SIGQUIT, or the terminal gone).
enum class TerminalInput { key, timeout, resize, stop };

// What the one terminal loop (run_program_on) needs of a terminal: its size, its keys, its cells,
// its pictures and a clock. Terminal is the real one (ncurses); the loop's tests drive it through a
// queue-backed fake, so that painting and key coalescing are tested without a terminal.
class TerminalDevice {
public:
    virtual ~TerminalDevice() = default;

    virtual TerminalSize size() const = 0;
    // Waits up to timeout_ms (negative: for ever, but still wakes for signals).
    virtual TerminalInput read_key(int timeout_ms, KeyEvent& key) = 0;
    // Shows the grid at the top-left, sending only what changed. True when every cell was sent
    // (the first call, after invalidate or redraw, or at a new size): a picture on the screen must
    // then be sent again.
    virtual bool show(const CellGrid& grid) = 0;
    // Forgets what is on the screen, so that the next show() repaints everything.
    virtual void invalidate() = 0;
    // And clears the terminal first (Ctrl-L: a screen garbled from outside made whole).
    virtual void redraw() = 0;

    // The size of a cell in screen pixels, where known.
    virtual std::optional<CellPixels> cell_pixels() const = 0;
    // The largest sixel picture the terminal said it shows, if it said.
    virtual std::optional<PictureLimit> sixel_limit() const = 0;
    // Writes a picture's sequences with its top-left corner at cell (column, row).
    virtual void send_picture(int column, int row, std::string_view sequences) = 0;
    // Takes every picture off the screen before characters take its place.
    virtual void remove_pictures(TerminalPictureProtocol protocol) = 0;

    // The loop's clock: how long the screen went unpainted while keys came, how long work ran.
    virtual std::chrono::steady_clock::time_point now() const { return std::chrono::steady_clock::now(); }
};

} // namespace apcs
