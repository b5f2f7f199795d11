#include "apcs/terminal/terminal_session.h"

#include "apcs/terminal/terminal.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>

namespace apcs {

namespace {

CellGrid too_small_grid(TerminalSize size)
{
    CellGrid grid(size.columns, size.rows);
    // The least fit_cell_area accepts: the character screen of graphics mode.
    const std::string message = "The terminal must be at least " + std::to_string(text_screen_columns) + "x" +
                                std::to_string(text_screen_rows) + " (it is " + std::to_string(size.columns) + "x" +
                                std::to_string(size.rows) + ")";
    const std::string keys = "Keys are ignored until it is larger; Ctrl-C quits";
    const int column = std::max(0, (size.columns - static_cast<int>(message.size())) / 2);
    grid.put_text(column, size.rows / 2, message);
    grid.put_text(std::max(0, (size.columns - static_cast<int>(keys.size())) / 2), size.rows / 2 + 1, keys);
    return grid;
}

CellGrid grid_for(const Session& session, TerminalSize size, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    const std::optional<CellArea> area = fit_cell_area(size.columns, size.rows);
    if (!area)
        return too_small_grid(size);
    const SessionScreen screen = session.screen();
    if (screen.graphics)
        return render_cells(screen.picture, *area, glyphs, cache);
    return screen.text;
}

// The session's work (the split) for about a frame's time, then back to the keys: Esc or Ctrl-C
// is read within that time, however many files are left.
void work_a_while(Session& session)
{
    constexpr auto slice = std::chrono::milliseconds(30);
    const auto start = std::chrono::steady_clock::now();
    do
        session.work();
    while (session.busy() && std::chrono::steady_clock::now() - start < slice);
}

} // namespace

ExitStatus run_terminal_session(Session& session, const std::vector<KeyEvent>& scripted, GlyphSet glyphs,
                                std::vector<KeyEvent>& recorded, Diagnostic& problem)
{
    Expected<std::unique_ptr<Terminal>> opened = Terminal::open();
    if (!opened) {
        problem = opened.error();
        return ExitStatus::terminal_problem;
    }
    const std::unique_ptr<Terminal> terminal = std::move(*opened);
    std::size_t next_scripted = 0;
    AsciiGlyphCache cache;
    while (!session.finished()) {
        terminal->show(grid_for(session, terminal->size(), glyphs, cache));
        KeyEvent key;
        TerminalInput input = TerminalInput::key;
        // A scripted key waits for the split, as a typed one would (Esc would stop it).
        if (next_scripted < scripted.size() && !session.animating() && !session.busy())
            key = scripted[next_scripted++];
        else
            input = terminal->read_key(session.busy() ? 0 : session.animating() ? session.delay_ms() : -1, key);
        switch (input) {
        case TerminalInput::stop:
            return ExitStatus::stopped;
        case TerminalInput::resize:
            terminal->invalidate();
            break;
        case TerminalInput::timeout:
            if (session.busy())
                work_a_while(session);
            else
                session.tick();
            break;
        case TerminalInput::key:
            // Ctrl-L repaints the whole terminal; the session sees the key too.
            if (key.key == Key::redraw)
                terminal->redraw();
            // Keys typed at the too-small screen would act on a session nobody can see.
            if (!fit_cell_area(terminal->size().columns, terminal->size().rows))
                break;
            recorded.push_back(key);
            session.handle(key);
            break;
        }
    }
    return ExitStatus::success;
}

} // namespace apcs
