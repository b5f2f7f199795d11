#include "apcs/terminal/terminal_player.h"

#include "apcs/session/key_map.h"
#include "apcs/terminal/terminal.h"
#include "apcs/terminal/terminal_session.h"

#include <memory>
#include <variant>

namespace apcs {

ExitStatus run_terminal_player(AnimationPlayer& player, int delay_ms, GlyphSet glyphs, const PictureSaver& save_picture,
                               Diagnostic& problem)
{
    const std::unique_ptr<Terminal> terminal = open_terminal(problem);
    if (!terminal)
        return ExitStatus::terminal_problem;
    AsciiGlyphCache cache;
    // ? shows the keys; the frames wait until a key closes the help.
    bool help = false;
    while (true) {
        const TerminalSize size = terminal->size();
        const bool fits = fit_cell_area(size.columns, size.rows).has_value();
        if (help && fits)
            terminal->show(key_help_screen("playing a scene", player.key_context()));
        else
            terminal->show(graphics_grid(player.view(), size, glyphs, cache));
        KeyEvent key;
        switch (terminal->read_key(player.playing() && !help ? delay_ms : -1, key)) {
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
            // Keys typed at the too-small screen would act on a player nobody can see.
            if (!fits)
                break;
            if (help) {
                help = false;
                break;
            }
            if (const std::optional<Command> command = command_for(player.key_context(), key)) {
                if (std::holds_alternative<command::Quit>(*command))
                    return ExitStatus::success;
                if (std::holds_alternative<command::ShowHelp>(*command)) {
                    help = true;
                    break;
                }
                if (std::holds_alternative<command::SavePicture>(*command)) {
                    player.show_notice(save_picture(player.view()));
                    break;
                }
                if (player.update(*command) == AnimationPlayer::Outcome::finished)
                    return ExitStatus::success;
            }
            break;
        }
    }
}

} // namespace apcs
