#include "apcs/terminal/terminal.h"

#include "apcs/terminal/curses_keys.h"
#include "stop_signals.h"

#include <curses.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <optional>
#include <string>
#include <unistd.h>

namespace apcs {

namespace {

// Esc alone counts after this many milliseconds unless the environment's ESCDELAY says otherwise.
constexpr int default_escape_delay_ms = 100;

Diagnostic terminal_problem(const std::string& message) { return Diagnostic{"apcs", 0, message}; }

} // namespace

struct Terminal::State {
    SCREEN* screen = nullptr;
    CellGrid shown;
    bool valid = false;
    // Installed once the terminal is taken over; destroyed after it is given back.
    std::optional<StopSignals> stop;
};

Terminal::Terminal() : m_state(std::make_unique<State>()) {}

Expected<std::unique_ptr<Terminal>> Terminal::open()
{
    if (!::isatty(STDIN_FILENO) || !::isatty(STDOUT_FILENO))
        return terminal_problem("standard input and output must be a terminal");
    const char* term = std::getenv("TERM");
    if (term == nullptr || *term == '\0')
        return terminal_problem("TERM is not set; set it to your terminal's type, e.g. TERM=xterm");
    std::unique_ptr<Terminal> terminal(new Terminal());
    State& state = *terminal->m_state;
    state.screen = newterm(term, stdout, stdin);
    if (state.screen == nullptr)
        return terminal_problem(std::string("the terminal type '") + term +
                                "' is unknown (no terminfo entry); try TERM=xterm");
    set_term(state.screen);
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    // Where terminfo names a sequence already, its meaning stands.
    for (const KeypadSequence& keypad_key : keypad_sequences())
        if (key_defined(keypad_key.sequence) == 0)
            define_key(keypad_key.sequence, keypad_key.code);
    // newterm has read the environment's ESCDELAY, if any.
    if (std::getenv("ESCDELAY") == nullptr)
        set_escdelay(default_escape_delay_ms);
    curs_set(0);
    state.stop.emplace();
    return terminal;
}

Terminal::~Terminal()
{
    if (m_state->screen != nullptr) {
        curs_set(1);
        endwin();
        delscreen(m_state->screen);
    }
}

TerminalSize Terminal::size() const
{
    int rows = 0;
    int columns = 0;
    getmaxyx(stdscr, rows, columns);
    return {columns, rows};
}

TerminalInput Terminal::read_key(int timeout_ms, KeyEvent& key)
{
    StopSignals& stop = *m_state->stop;
    const auto start = std::chrono::steady_clock::now();
    while (true) {
        if (stop.requested())
            return TerminalInput::stop;
        int wait = 100;
        if (timeout_ms >= 0) {
            const auto elapsed = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count();
            if (elapsed >= timeout_ms)
                return TerminalInput::timeout;
            wait = static_cast<int>(std::min<long long>(100, timeout_ms - elapsed));
        }
        timeout(wait);
        wint_t code = 0;
        const int kind = get_wch(&code);
        if (kind == ERR) {
            // A closed terminal reads as end of file at once, again and again. It is a hang-up
            // whose SIGHUP may still be on its way: count it as one.
            if (!::isatty(STDIN_FILENO)) {
                stop.request();
                return TerminalInput::stop;
            }
            continue;
        }
        if (kind == KEY_CODE_YES && code == KEY_RESIZE)
            return TerminalInput::resize;
        if (const std::optional<KeyEvent> event = key_event_from_curses(kind, code)) {
            key = *event;
            return TerminalInput::key;
        }
    }
}

void Terminal::invalidate() { m_state->valid = false; }

void Terminal::show(const CellGrid& grid)
{
    State& state = *m_state;
    const bool full = !state.valid || state.shown.columns() != grid.columns() || state.shown.rows() != grid.rows();
    if (full)
        erase();
    for (int row = 0; row < grid.rows(); ++row) {
        int column = 0;
        while (column < grid.columns()) {
            if (!full && grid.at(column, row) == state.shown.at(column, row)) {
                ++column;
                continue;
            }
            // A run of changed cells goes out as one string.
            std::string run;
            const int start = column;
            while (column < grid.columns() && (full || grid.at(column, row) != state.shown.at(column, row))) {
                append_utf8(run, grid.at(column, row));
                ++column;
            }
            mvaddstr(row, start, run.c_str());
        }
    }
    refresh();
    state.shown = grid;
    state.valid = true;
}

} // namespace apcs
