#include "terminal.h"

#include "apcs/terminal/curses_keys.h"
#include "stop_signals.h"
#include "write_all.h"

#include <curses.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <poll.h>
#include <string>
#include <string_view>
#include <sys/ioctl.h>
#include <unistd.h>

namespace apcs {

namespace {

// Esc alone counts after this many milliseconds unless the environment's ESCDELAY says otherwise.
constexpr int default_escape_delay_ms = 100;

Diagnostic terminal_problem(const std::string& message) { return Diagnostic{"apcs", 0, message}; }

Diagnostic no_full_screen(const std::string& term)
{
    return terminal_problem("the terminal type '" + term +
                            "' cannot show a full screen (it cannot move the cursor); try TERM=xterm");
}

// Whether terminfo gives the terminal a way to move the cursor (cup), the least a full screen needs.
bool can_move_cursor()
{
    const char* const move = tigetstr("cup");
    return move != nullptr && move != reinterpret_cast<const char*>(static_cast<std::intptr_t>(-1));
}

attr_t attributes_of(CellStyle style)
{
    switch (style) {
    case CellStyle::bold: return A_BOLD;
    case CellStyle::reverse: return A_REVERSE;
    case CellStyle::plain: break;
    }
    return A_NORMAL;
}

// Colour pair n + 1 for the role of index n after monitor (monitor is pair 0: the default colours),
// in the terminal's own colours where terminfo says how to give them back (op or oc), on black
// where it does not (use_default_colors fails, and a pair on -1 would then fail too, leaving the
// roles in unmade pairs: black on black). A role in the terminal's own foreground (-1) is white
// there. False when the pairs cannot be made: the roles are then told apart without colour, as
// with --color never.
// A bright colour (8-15) on a terminal of 8 is its colour of 0-7 in bold, which xterm and the
// Linux console show bright.
bool start_role_colours()
{
    if (start_color() == ERR)
        return false;
    const bool own_colours = use_default_colors() == OK;
    const short background = own_colours ? -1 : COLOR_BLACK;
    for (const ColourRole role : colour_roles) {
        if (role == ColourRole::monitor)
            continue;
        const int number = colour_number(role) >= COLORS ? colour_number(role) - 8 : colour_number(role);
        const short foreground = static_cast<short>(number >= 0 || own_colours ? number : COLOR_WHITE);
        if (init_pair(static_cast<short>(role), foreground, background) == ERR)
            return false;
    }
    return true;
}

// Bold where a role's bright colour is beyond the terminal's (start_role_colours).
attr_t bright_by_bold(ColourRole role) { return colour_number(role) >= COLORS ? A_BOLD : A_NORMAL; }

bool colour_wanted(ColourChoice colour)
{
    if (colour == ColourChoice::never || !has_colors())
        return false;
    // COLORS is known only after start_color: terminfo's count is asked instead.
    return colour == ColourChoice::always || tigetnum("colors") >= 8;
}

// The most bytes one question reads: a terminal answering garbage is not read for ever.
constexpr std::size_t most_reply_bytes = 4096;
// The most bytes typed during the questions that go back to curses as keys: its input queue
// (ungetch) holds 137 and overran with more, repeating keys for ever. More is a paste or garbage
// that came before the reply, dropped with it.
constexpr std::size_t most_typed_ahead = 64;

// Whether `byte` can end a reply: a CSI's final byte (c, S, t) or an APC string's ESC \.
bool may_end_reply(char byte) { return byte == 'c' || byte == 'S' || byte == 't' || byte == '\\'; }

// Asks `query` and reads what comes back until `answered` holds for the replies read or
// pixel_reply_limit_ms have passed since the question: a terminal that does not answer costs that
// long, never more. One byte a read, so that what follows the reply (keys typed after it, however
// many) stays in the terminal's queue for curses to read.
template <typename Answered>
TerminalReplies ask_terminal(std::string_view query, Answered answered)
{
    write_all(STDOUT_FILENO, query);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(pixel_reply_limit_ms);
    std::string bytes;
    while (bytes.size() < most_reply_bytes) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0)
            break;
        pollfd input{STDIN_FILENO, POLLIN, 0};
        const int ready = ::poll(&input, 1, static_cast<int>(left));
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready <= 0 || (input.revents & POLLIN) == 0)
            break;
        char byte = 0;
        if (::read(STDIN_FILENO, &byte, 1) != 1)
            break;
        bytes += byte;
        if (may_end_reply(byte) && answered(read_terminal_replies(bytes)))
            break;
    }
    return read_terminal_replies(bytes);
}

// TIOCGWINSZ's cell size, where the terminal fills in its pixels.
std::optional<CellPixels> window_cell_pixels()
{
    winsize size{};
    if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) != 0)
        return std::nullopt;
    return cell_from_window(size.ws_xpixel, size.ws_ypixel, size.ws_col, size.ws_row);
}

} // namespace

// What get_wch gave: its result (OK, KEY_CODE_YES) and the character or key code.
struct RawKey {
    int kind = ERR;
    wint_t code = 0;
};

struct Terminal::State {
    SCREEN* screen = nullptr;
    CellGrid shown;
    bool valid = false;
    bool colour = false;
    // A key code read while deciding what an Esc was, handed out next.
    std::optional<RawKey> pending;
    // Installed before the terminal is taken over; destroyed after it is given back.
    std::optional<StopSignals> stop;
    // The cell size the terminal answered to CSI 16 t (detect_pixels), for when TIOCGWINSZ has none.
    std::optional<CellPixels> answered_cell;
    // The largest sixel picture it shows, as it answered (detect_pixels).
    std::optional<PictureLimit> sixel_limit;

    // After get_wch gave an Esc: whether it is the Esc key (true) or the start of an escape
    // sequence that ncurses does not know, read to its end and dropped (false). What follows the
    // Esc and is not part of a sequence is kept for the next reads.
    bool escape_stands();
};

bool Terminal::State::escape_stands()
{
    std::u32string tail;
    // ncurses returned the Esc alone after ESCDELAY, or at once when what followed matched no key:
    // then the rest is here already, or comes within ESCDELAY.
    timeout(0);
    while (true) {
        wint_t code = 0;
        const int kind = get_wch(&code);
        if (kind == ERR)
            return tail.empty(); // the Esc alone, or a sequence cut short: dropped
        if (kind == KEY_CODE_YES) {
            // A key ncurses decoded after the Esc (Esc, then an arrow): both count.
            pending = RawKey{kind, code};
            return tail.empty();
        }
        tail += static_cast<char32_t>(code);
        switch (escape_tail(tail)) {
        case EscapeTail::unfinished:
            timeout(get_escdelay());
            break;
        case EscapeTail::sequence:
            return false;
        case EscapeTail::broken:
            unget_wch(static_cast<wchar_t>(tail.back()));
            return false;
        case EscapeTail::keys:
            unget_wch(static_cast<wchar_t>(tail.back()));
            return true;
        }
    }
}

Terminal::Terminal() : m_state(std::make_unique<State>()) {}

Expected<std::unique_ptr<Terminal>> Terminal::open(ColourChoice colour)
{
    if (!::isatty(STDIN_FILENO) || !::isatty(STDOUT_FILENO))
        return terminal_problem("standard input and output must be a terminal");
    const char* term = std::getenv("TERM");
    if (term == nullptr || *term == '\0')
        return terminal_problem("TERM is not set; set it to your terminal's type, e.g. TERM=xterm");
    if (std::string_view(term) == "dumb")
        return no_full_screen(term);
    std::unique_ptr<Terminal> terminal(new Terminal());
    State& state = *terminal->m_state;
    // Before the terminal's modes change: a signal from here on is a stop that read_key reports
    // and the destructor gives the terminal back after, never the batch commands' _exit, which
    // would leave it raw (cbreak, noecho).
    state.stop.emplace();
    state.screen = newterm(term, stdout, stdin);
    if (state.screen == nullptr)
        return terminal_problem(std::string("the terminal type '") + term +
                                "' is unknown (no terminfo entry); try TERM=xterm");
    set_term(state.screen);
    // A hard-copy or glass terminal under another name: given back by the destructor.
    if (!can_move_cursor())
        return no_full_screen(term);
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    // Where terminfo names a sequence already, its meaning stands.
    for (const KeySequence& key : key_sequences())
        if (key_defined(key.sequence) == 0)
            define_key(key.sequence, key.code);
    // newterm has read the environment's ESCDELAY, if any.
    if (std::getenv("ESCDELAY") == nullptr)
        set_escdelay(default_escape_delay_ms);
    // Until curses has been left and resumed once, ncurses 6.4 writes out what it has at every
    // cursor move (lib_mvcur.c, while SP->_endwin is ewInitial): a screen's changes went out in 8 to
    // 17 writes, each an SSH packet of its own (36 bytes more each). Left and resumed before anything
    // is drawn, it writes each refresh at once.
    endwin();
    refresh();
    curs_set(0);
    state.colour = colour_wanted(colour) && start_role_colours();
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
    State& state = *m_state;
    StopSignals& stop = *state.stop;
    const auto start = std::chrono::steady_clock::now();
    // A time-out of 0 still looks once for a key typed meanwhile (between batches of work).
    bool looked = false;
    while (true) {
        if (stop.requested())
            return TerminalInput::stop;
        int wait = 100;
        if (timeout_ms >= 0) {
            const auto elapsed = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count();
            if (elapsed >= timeout_ms && !state.pending && looked)
                return TerminalInput::timeout;
            wait = static_cast<int>(std::clamp<long long>(timeout_ms - elapsed, 0, 100));
        }
        RawKey raw;
        if (state.pending) {
            raw = *state.pending;
            state.pending.reset();
        } else {
            timeout(wait);
            raw.kind = get_wch(&raw.code);
            looked = true;
        }
        if (raw.kind == ERR) {
            // A closed terminal reads as end of file at once, again and again. It is a hang-up
            // whose SIGHUP may still be on its way: count it as one.
            if (!::isatty(STDIN_FILENO)) {
                stop.request();
                return TerminalInput::stop;
            }
            continue;
        }
        if (raw.kind == KEY_CODE_YES && raw.code == KEY_RESIZE)
            return TerminalInput::resize;
        if (raw.kind == OK && raw.code == 27 && !state.escape_stands())
            continue;
        if (const std::optional<KeyEvent> event = key_event_from_curses(raw.kind, raw.code)) {
            key = *event;
            return TerminalInput::key;
        }
    }
}

void Terminal::invalidate() { m_state->valid = false; }

void Terminal::redraw()
{
    m_state->valid = false;
    // The next refresh clears the terminal and sends every line, whatever curses thinks is there.
    clearok(curscr, TRUE);
    redrawwin(stdscr);
}

PixelDecision Terminal::detect_pixels(PixelChoice choice)
{
    if (const std::optional<PixelDecision> decided =
            decide_before_asking(choice, multiplexer_around(std::getenv("TMUX"), std::getenv("STY"), std::getenv("TERM"))))
        return *decided;
    // What curses has to say goes out before the questions.
    refresh();
    const auto attributes_came = [](const TerminalReplies& replies) { return replies.device_attributes.has_value(); };
    TerminalReplies replies =
        ask_terminal(std::string(sixel_limit_query) + std::string(device_attributes_query), attributes_came);
    m_state->sixel_limit = replies.sixel_limit;
    std::string typed = replies.other;
    if (asks_kitty(choice) && replies.device_attributes) {
        // The device attributes asked again after it: every terminal answers them, so their
        // answer ends the wait for a kitty reply that does not come.
        const TerminalReplies kitty = ask_terminal(std::string(kitty_graphics_query) + std::string(device_attributes_query), attributes_came);
        replies.kitty = kitty.kitty;
        typed += kitty.other;
    }
    PixelDecision decision = decide_protocol(choice, replies);
    if (decision.protocol && !window_cell_pixels()) {
        const TerminalReplies cell = ask_terminal(cell_size_query, [](const TerminalReplies& answered) { return answered.cell.has_value(); });
        m_state->answered_cell = cell.cell;
        typed += cell.other;
        if (!cell.cell)
            decision = PixelDecision{std::nullopt, std::string(no_cell_size_line)};
    }
    // Keys typed during the questions are read next, in the order typed (ungetch pushes in front).
    if (typed.size() <= most_typed_ahead)
        for (auto key = typed.rbegin(); key != typed.rend(); ++key)
            ungetch(static_cast<unsigned char>(*key));
    // A terminal that knows no APC string (the Linux console) may have printed the kitty query's
    // text: the first screen clears the terminal.
    redraw();
    return decision;
}

std::optional<CellPixels> Terminal::cell_pixels() const
{
    if (const std::optional<CellPixels> cell = window_cell_pixels())
        return cell;
    return m_state->answered_cell;
}

std::optional<PictureLimit> Terminal::sixel_limit() const { return m_state->sixel_limit; }

void Terminal::send_picture(int column, int row, std::string_view sequences)
{
    // DECSC, the cursor to the picture's top-left cell, the picture, DECRC.
    std::string bytes = "\x1b" "7\x1b[" + std::to_string(row + 1) + ";" + std::to_string(column + 1) + "H";
    bytes += sequences;
    bytes += "\x1b" "8";
    write_all(STDOUT_FILENO, bytes, [this] { return m_state->stop->requested(); });
}

void Terminal::remove_pictures(TerminalPictureProtocol protocol)
{
    // Kitty: delete every placement and free its image (d=A).
    if (protocol == TerminalPictureProtocol::kitty)
        write_all(STDOUT_FILENO, "\x1b_Ga=d,d=A,q=2\x1b\\");
}

bool Terminal::show(const CellGrid& grid)
{
    State& state = *m_state;
    const bool full = !state.valid || state.shown.columns() != grid.columns() || state.shown.rows() != grid.rows();
    if (full)
        erase();
    const auto changed = [&](int column, int row) {
        return full || grid.at(column, row) != state.shown.at(column, row) ||
               grid.marks_at(column, row) != state.shown.marks_at(column, row) ||
               grid.style_at(column, row) != state.shown.style_at(column, row) ||
               (state.colour && grid.role_at(column, row) != state.shown.role_at(column, row));
    };
    for (int row = 0; row < grid.rows(); ++row) {
        int column = 0;
        while (column < grid.columns()) {
            if (!changed(column, row)) {
                ++column;
                continue;
            }
            // A run of changed cells of one style goes out as one string. A wide character is sent
            // once, from its left cell, which the terminal fills with both halves.
            if (grid.at(column, row) == CellGrid::wide_tail && column > 0)
                --column;
            const CellStyle style = grid.style_at(column, row);
            const short pair = state.colour ? static_cast<short>(grid.role_at(column, row)) : 0;
            std::string run;
            const int start = column;
            const auto continues_run = [&](int next) {
                return grid.at(next, row) == CellGrid::wide_tail ||
                       (changed(next, row) && grid.style_at(next, row) == style &&
                        (!state.colour || static_cast<short>(grid.role_at(next, row)) == pair));
            };
            // A cell's combining marks follow its character: ncurses puts them in that cell.
            while (column < grid.columns() && (column == start || continues_run(column))) {
                if (grid.at(column, row) != CellGrid::wide_tail)
                    append_utf8(run, grid.at(column, row));
                for (const char32_t mark : grid.marks_at(column, row))
                    append_utf8(run, mark);
                ++column;
            }
            attr_set(attributes_of(style) | bright_by_bold(static_cast<ColourRole>(pair)), pair, nullptr);
            mvaddstr(row, start, run.c_str());
        }
    }
    attr_set(A_NORMAL, 0, nullptr);
    refresh();
    state.shown = grid;
    state.valid = true;
    return full;
}

} // namespace apcs
