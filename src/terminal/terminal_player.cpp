#include "apcs/terminal/terminal_player.h"

#include "apcs/session/key_map.h"
#include "apcs/terminal/terminal.h"
#include "apcs/terminal/terminal_session.h"

#include <memory>
#include <variant>

namespace apcs {

ExitStatus run_terminal_player(AnimationPlayer& player, int delay_ms, GlyphSet glyphs, Diagnostic& problem)
{
    Expected<std::unique_ptr<Terminal>> opened = Terminal::open();
    if (!opened) {
        problem = opened.error();
        return ExitStatus::terminal_problem;
    }
    const std::unique_ptr<Terminal> terminal = std::move(*opened);
    AsciiGlyphCache cache;
    while (true) {
        const TerminalSize size = terminal->size();
        const std::optional<CellArea> area = fit_cell_area(size.columns, size.rows);
        terminal->show(area ? render_cells(player.view(), *area, glyphs, cache) : too_small_grid(size));
        KeyEvent key;
        switch (terminal->read_key(player.playing() ? delay_ms : -1, key)) {
        case TerminalInput::stop:
            return ExitStatus::stopped;
        case TerminalInput::resize:
            terminal->invalidate();
            break;
        case TerminalInput::timeout:
            player.tick();
            break;
        case TerminalInput::key:
            if (key.key == Key::redraw) {
                terminal->redraw();
                break;
            }
            if (!area)
                break;
            if (const std::optional<Command> command = command_for(player.key_context(), key)) {
                if (std::holds_alternative<command::Quit>(*command))
                    return ExitStatus::success;
                if (player.update(*command) == AnimationPlayer::Outcome::finished)
                    return ExitStatus::success;
            }
            break;
        }
    }
}

} // namespace apcs
