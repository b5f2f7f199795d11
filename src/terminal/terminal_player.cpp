#include "apcs/terminal/terminal_player.h"

#include "apcs/session/scene_player.h"
#include "apcs/terminal/terminal_session.h"

namespace apcs {

Expected<ExitStatus> run_terminal_player(AnimationPlayer& player, int delay_ms, GlyphSet glyphs, PixelChoice pixels,
                                         const PictureSaver& save_picture)
{
    ScenePlayer program(player, delay_ms, save_picture);
    std::vector<KeyEvent> typed;
    return run_terminal_session(program, KeyScript{}, ReplayPace{}, glyphs, ColourChoice::never, pixels, typed);
}

} // namespace apcs
