#include "apcs/terminal/program_loop.h"

#include "apcs/input/play_to_idle.h"
#include "apcs/screens/replay_caption.h"
#include "apcs/screens/short_screen.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace apcs {

namespace {

CellGrid grid_for(const ProgramScreen& screen, TerminalSize size, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    const std::optional<CellArea> area = fit_cell_area(size.columns, size.rows);
    if (!area)
        return too_small_grid(size);
    if (screen.graphics)
        return with_played_key(graphics_grid(screen.picture, size, glyphs, cache), screen.badge, screen.badge_place);
    // The badge goes on after a row is left out, so that it stays on the top row.
    return with_played_key(is_short_area(*area) ? text_on_short_screen(screen.text) : screen.text, screen.badge,
                           screen.badge_place);
}

// The program's screen on the terminal: characters through curses and, where --pixels shows the
// drawing area as a picture, the picture over the rows curses leaves blank. The screen's caption,
// else why pictures are off (until a key is typed), goes on the caption row (with_caption).
void show_screen(TerminalDevice& terminal, TerminalPixels& pixels, const InteractiveProgram& program, GlyphSet glyphs,
                 AsciiGlyphCache& cache)
{
    ProgramScreen screen = program.screen();
    const std::string caption = screen.caption.empty() ? std::string(pixels.notice()) : std::move(screen.caption);
    screen = with_caption(std::move(screen), caption);
    const TerminalSize size = terminal.size();
    const std::optional<PictureFrame> frame = screen.graphics ? pixels.frame_for(size) : std::nullopt;
    pixels.before_show(frame);
    CellGrid grid = grid_for(screen, size, glyphs, cache);
    if (frame)
        grid = without_rows(std::move(grid), frame->blank_rows);
    const bool repainted = terminal.show(grid);
    if (frame)
        pixels.show(screen.picture, *frame, repainted);
}

// The program's work (the split, a replay's keys played at once) for about a frame's time, then
// back to the keys: Esc or Ctrl-C is read within that time, however much is left.
void work_a_while(InteractiveProgram& program, const TerminalDevice& terminal)
{
    constexpr auto slice = std::chrono::milliseconds(30);
    const auto start = terminal.now();
    IdleDrive drive;
    drive.animations = Animations::stop_at; // the loop's clock ticks them
    drive.go_on = [&] { return terminal.now() - start < slice; };
    play_to_idle(program, drive);
}

// A key read: to the program, unless the terminal is too small to show it. True when the whole
// terminal must be painted again (Ctrl-L, which the program sees too; the pixel notice gone).
bool take_key(const KeyEvent& key, TerminalDevice& terminal, TerminalPixels& pixels, InteractiveProgram& program)
{
    bool changed = false;
    if (key.key == Key::redraw) {
        terminal.redraw();
        changed = true;
    }
    // Keys typed at the too-small screen would act on a program nobody can see.
    if (!fit_cell_area(terminal.size().columns, terminal.size().rows))
        return changed;
    if (!pixels.notice().empty()) {
        pixels.clear_notice();
        changed = true;
    }
    program.handle(key);
    return changed;
}

} // namespace

CellGrid too_small_grid(TerminalSize size)
{
    CellGrid grid(size.columns, size.rows);
    // The least fit_cell_area accepts: the short screen.
    const std::string message = "The terminal must be at least " + std::to_string(text_screen_columns) + "x" +
                                std::to_string(short_screen_rows) + " (it is " + std::to_string(size.columns) + "x" +
                                std::to_string(size.rows) + ")";
    const std::string keys = "Keys are ignored until it is larger; Ctrl-C quits";
    const int column = std::max(0, (size.columns - static_cast<int>(message.size())) / 2);
    grid.put_text(column, size.rows / 2, message);
    grid.put_text(std::max(0, (size.columns - static_cast<int>(keys.size())) / 2), size.rows / 2 + 1, keys);
    return grid;
}

CellGrid graphics_grid(const GraphicsScreen& screen, TerminalSize size, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    const std::optional<CellArea> area = fit_cell_area(size.columns, size.rows);
    return area ? render_screen_cells(screen, *area, glyphs, cache) : too_small_grid(size);
}

ExitStatus run_program_on(InteractiveProgram& program, TerminalDevice& terminal, TerminalPixels& pixels,
                          GlyphSet glyphs)
{
    AsciiGlyphCache cache;
    // The revision of the screen painted last, and whether the terminal changed since (nothing
    // painted yet, a resize, Ctrl-L, the notice gone).
    std::uint64_t painted = 0;
    bool terminal_changed = true;
    // Keys that came together (a paste, a held key, a terminal's flood) are all taken before the
    // screen is painted again, but the screen is never older than a tenth of a second.
    bool keys_waiting = false;
    auto painted_at = terminal.now();
    constexpr auto longest_unpainted = std::chrono::milliseconds(100);
    while (!program.finished()) {
        const auto now = terminal.now();
        if ((terminal_changed || painted != program.screen_revision()) &&
            (!keys_waiting || now - painted_at >= longest_unpainted)) {
            show_screen(terminal, pixels, program, glyphs, cache);
            painted = program.screen_revision();
            terminal_changed = false;
            painted_at = now;
        }
        KeyEvent key;
        const int wait_ms = keys_waiting || program.busy() ? 0 : program.animating() ? program.delay_ms() : -1;
        const TerminalInput input = terminal.read_key(wait_ms, key);
        const bool looked_for_more = std::exchange(keys_waiting, input == TerminalInput::key);
        switch (input) {
        case TerminalInput::stop:
            return ExitStatus::stopped;
        case TerminalInput::resize:
            terminal.invalidate();
            terminal_changed = true;
            break;
        case TerminalInput::timeout:
            if (looked_for_more)
                break; // no more keys: paint first
            if (program.busy())
                work_a_while(program, terminal);
            else
                program.tick();
            break;
        case TerminalInput::key:
            terminal_changed = take_key(key, terminal, pixels, program) || terminal_changed;
            break;
        }
    }
    return ExitStatus::success;
}

} // namespace apcs
