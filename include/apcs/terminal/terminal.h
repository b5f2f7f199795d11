#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/session/key_event.h"

#include <memory>

namespace apcs {

struct TerminalSize {
    int columns = 0;
    int rows = 0;
};

// What read_key saw: a key, nothing within the time-out, a resize, or a request to stop
// (SIGINT, SIGTERM, SIGHUP, SIGQUIT, or the terminal gone).
enum class TerminalInput { key, timeout, resize, stop };

// The one door to the terminal (ncurses). Construction takes over the terminal; destruction, a
// signal or an exception in the program gives it back as it was (echo and line mode on).
class Terminal {
public:
    // The terminal, or why there is no usable one (TERM unset, unknown or `dumb`, a terminal that
    // cannot move its cursor, stdin or stdout not a terminal) as "apcs: PROBLEM". Keys are
    // decoded by ncurses (keypad, with the sequences of key_sequences() bound by define_key); Esc
    // counts after ESCDELAY ms, the environment's, else 100 (SPEC §7.3).
    // `colour`: automatic draws the cells' colour roles where the terminal has colours (has_colors
    // and at least 8), always where it has any, never in the default colours only.
    [[nodiscard]] static Expected<std::unique_ptr<Terminal>> open(ColourChoice colour = ColourChoice::never);
    ~Terminal();
    Terminal(const Terminal&) = delete;
    Terminal& operator=(const Terminal&) = delete;

    TerminalSize size() const;
    // Waits up to timeout_ms (negative: for ever, but still wakes for signals). An escape
    // sequence ncurses does not know is read to its end and dropped, never typed (escape_tail).
    TerminalInput read_key(int timeout_ms, KeyEvent& key);
    // Shows the grid at the top-left, each cell in its style (bold, reverse video) and, with colour,
    // its role's colour, sending only the cells whose character, style or role changed since the last call; a run of changed cells of
    // one style goes out as one string.
    void show(const CellGrid& grid);
    // Forgets what is on the screen, so that the next show() repaints everything.
    void invalidate();
    // Forgets what is on the screen and what curses believes is there: the next show() clears
    // the terminal and repaints every cell, so a screen garbled from outside is made whole (Ctrl-L).
    void redraw();

private:
    Terminal();
    struct State;
    std::unique_ptr<State> m_state;
};

} // namespace apcs
