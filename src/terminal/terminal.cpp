#include "apcs/terminal/terminal.h"

#include <curses.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace apcs {

namespace {

volatile std::sig_atomic_t stop_requested = 0;

// One stop is enough: from the first signal on the others are ignored (sigaction is
// async-signal-safe), so that a hang-up's second SIGHUP cannot cut short the writing of files.
extern "C" void request_stop(int)
{
    stop_requested = 1;
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGINT, &ignore, nullptr);
    sigaction(SIGTERM, &ignore, nullptr);
    sigaction(SIGHUP, &ignore, nullptr);
}

} // namespace

struct Terminal::State {
    SCREEN* screen = nullptr;
    CellGrid shown;
    bool valid = false;
    struct sigaction old_int {};
    struct sigaction old_term {};
    struct sigaction old_hup {};
};

Terminal::Terminal() : m_state(std::make_unique<State>()) {}

std::unique_ptr<Terminal> Terminal::open(std::string& problem)
{
    if (!::isatty(STDIN_FILENO) || !::isatty(STDOUT_FILENO)) {
        problem = "standard input and output must be a terminal";
        return nullptr;
    }
    const char* term = std::getenv("TERM");
    if (term == nullptr || *term == '\0') {
        problem = "TERM is not set; set it to your terminal's type, e.g. TERM=xterm";
        return nullptr;
    }
    std::unique_ptr<Terminal> terminal(new Terminal());
    State& state = *terminal->m_state;
    state.screen = newterm(term, stdout, stdin);
    if (state.screen == nullptr) {
        problem = std::string("the terminal type '") + term + "' is unknown (no terminfo entry); try TERM=xterm";
        return nullptr;
    }
    set_term(state.screen);
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    set_escdelay(25);
    curs_set(0);
    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &state.old_int);
    sigaction(SIGTERM, &action, &state.old_term);
    sigaction(SIGHUP, &action, &state.old_hup);
    stop_requested = 0;
    return terminal;
}

Terminal::~Terminal()
{
    if (m_state->screen != nullptr) {
        curs_set(1);
        endwin();
        delscreen(m_state->screen);
    }
    if (stop_requested) {
        // After a stop the program only finishes its files; a second hang-up (the kernel sends one
        // when the terminal's session leader goes) must not cut that short.
        sigset_t finishing;
        sigemptyset(&finishing);
        for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE})
            sigaddset(&finishing, signal);
        sigprocmask(SIG_BLOCK, &finishing, nullptr);
        return;
    }
    sigaction(SIGINT, &m_state->old_int, nullptr);
    sigaction(SIGTERM, &m_state->old_term, nullptr);
    sigaction(SIGHUP, &m_state->old_hup, nullptr);
}

TerminalSize Terminal::size() const
{
    int rows = 0;
    int columns = 0;
    getmaxyx(stdscr, rows, columns);
    return {columns, rows};
}

namespace {

// Keypad keys in application mode with NumLock off arrive as ESC O x when terminfo does not
// name them: t = 4, v = 6, x = 8, r = 2, M = Enter.
std::optional<KeyEvent> keypad_sequence(wint_t final)
{
    switch (final) {
    case 't': return KeyEvent::typed(U'4');
    case 'v': return KeyEvent::typed(U'6');
    case 'x': return KeyEvent::typed(U'8');
    case 'r': return KeyEvent::typed(U'2');
    case 'M': return KeyEvent::of(Key::enter);
    default: return std::nullopt;
    }
}

} // namespace

TerminalInput Terminal::read_key(int timeout_ms, KeyEvent& key)
{
    const auto start = std::chrono::steady_clock::now();
    while (true) {
        if (stop_requested)
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
                stop_requested = 1;
                return TerminalInput::stop;
            }
            continue;
        }
        if (kind == KEY_CODE_YES) {
            switch (code) {
            case KEY_RESIZE: return TerminalInput::resize;
            case KEY_LEFT: key = KeyEvent::of(Key::left); return TerminalInput::key;
            case KEY_RIGHT: key = KeyEvent::of(Key::right); return TerminalInput::key;
            case KEY_UP: key = KeyEvent::of(Key::up); return TerminalInput::key;
            case KEY_DOWN: key = KeyEvent::of(Key::down); return TerminalInput::key;
            case KEY_ENTER: key = KeyEvent::of(Key::enter); return TerminalInput::key;
            case KEY_BACKSPACE: key = KeyEvent::of(Key::backspace); return TerminalInput::key;
            default: continue;
            }
        }
        switch (code) {
        case '\r':
        case '\n': key = KeyEvent::of(Key::enter); return TerminalInput::key;
        case ' ': key = KeyEvent::of(Key::space); return TerminalInput::key;
        case 8:
        case 127: key = KeyEvent::of(Key::backspace); return TerminalInput::key;
        case 27: {
            timeout(25);
            wint_t next = 0;
            if (get_wch(&next) == OK && next == 'O') {
                wint_t final = 0;
                if (get_wch(&final) == OK)
                    if (const auto mapped = keypad_sequence(final)) {
                        key = *mapped;
                        return TerminalInput::key;
                    }
                continue;
            }
            if (next != 0)
                unget_wch(static_cast<wchar_t>(next));
            key = KeyEvent::of(Key::escape);
            return TerminalInput::key;
        }
        default:
            if (code >= 0x20) {
                key = KeyEvent::typed(static_cast<char32_t>(code));
                return TerminalInput::key;
            }
            continue;
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
