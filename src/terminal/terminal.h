#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/pixel_picture.h"
#include "apcs/terminal/pixel_detection.h"
#include "apcs/terminal/terminal_device.h"
#include "apcs/formats/key_event.h"

#include <memory>
#include <optional>
#include <string_view>

namespace apcs {

// The one door to the terminal (ncurses). Construction takes over the terminal; destruction, a
// signal or an exception in the program gives it back as it was (echo and line mode on).
class Terminal final : public TerminalDevice {
public:
    // The terminal, or why there is no usable one (TERM unset, unknown or `dumb`, a terminal that
    // cannot move its cursor, stdin or stdout not a terminal) as "apcs: PROBLEM". Keys are
    // decoded by ncurses (keypad, with the sequences of key_sequences() bound by define_key); Esc
    // counts after ESCDELAY ms, the environment's, else 100 (SPEC §7.3).
    // `colour`: automatic draws the cells' colour roles where the terminal has colours (has_colors
    // and at least 8), always where it has any, never in the default colours only.
    [[nodiscard]] static Expected<std::unique_ptr<Terminal>> open(ColourChoice colour = ColourChoice::never);
    ~Terminal() override;
    Terminal(const Terminal&) = delete;
    Terminal& operator=(const Terminal&) = delete;

    TerminalSize size() const override;
    // Waits up to timeout_ms (negative: for ever, but still wakes for signals). An escape
    // sequence ncurses does not know is read to its end and dropped, never typed (escape_tail).
    TerminalInput read_key(int timeout_ms, KeyEvent& key) override;
    // Shows the grid at the top-left, each cell in its style (bold, reverse video) and, with colour,
    // its role's colour, sending only the cells whose character, style or role changed since the last call; a run of changed cells of
    // one style goes out as one string. True when every cell was sent (the first call, after
    // invalidate or redraw, or at a new size): a picture on the screen must then be sent again.
    bool show(const CellGrid& grid) override;
    // Forgets what is on the screen, so that the next show() repaints everything.
    void invalidate() override;
    // Forgets what is on the screen and what curses believes is there: the next show() clears
    // the terminal and repaints every cell, so a screen garbled from outside is made whole (Ctrl-L).
    void redraw() override;

    // --pixels (SPEC §7.2.1): which picture protocol this terminal shows, or why none (one line).
    // Off asks nothing; inside tmux or screen nothing is asked either. Otherwise the device
    // attributes, then (auto, kitty) the kitty graphics query, then where TIOCGWINSZ gives no pixel
    // size the cell size, each answered within pixel_reply_limit_ms or taken as unanswered: never a
    // hang. Keys typed meanwhile are kept for read_key; a reply that comes late is dropped there as
    // an escape sequence nobody knows (escape_tail); the next show() clears the terminal, in case
    // it printed a question it did not know. Call once, before the first show().
    PixelDecision detect_pixels(PixelChoice choice);
    // The size of a cell in screen pixels: TIOCGWINSZ's (asked anew, the font may have changed),
    // else what the terminal answered to detect_pixels' cell size query; nullopt when neither.
    std::optional<CellPixels> cell_pixels() const override;
    // The largest sixel picture the terminal said it shows (detect_pixels), if it said.
    std::optional<PictureLimit> sixel_limit() const override;
    // Writes `sequences` (a picture: sixel or kitty) with its top-left corner at cell (column,
    // row), counted from 0; the cursor and what curses believes is on the screen stay as they were
    // (DECSC, DECRC around it). Call after show(): curses' output goes first.
    void send_picture(int column, int row, std::string_view sequences) override;
    // Takes every picture off the screen before characters take its place: kitty keeps its
    // pictures over cleared text, so they are deleted; sixel pixels go with the next redraw().
    void remove_pictures(TerminalPictureProtocol protocol) override;

private:
    Terminal();
    struct State;
    std::unique_ptr<State> m_state;
};

} // namespace apcs
