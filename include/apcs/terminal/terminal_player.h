#pragma once

#include "apcs/formats/diagnostic.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/session/animation_player.h"
#include "apcs/session/exit_status.h"

#include <functional>
#include <string>

namespace apcs {

// Writes the screen shown as a picture (P) and says what happened, for the message line.
using PictureSaver = std::function<std::string(const GraphicsScreen& screen)>;

// Plays `player` in the terminal (apcs play): a frame every `delay_ms` while it plays, Esc, Space
// and R as in the session's animation, then all frames overlaid until a key ends it; q ends it at
// once, ? shows the keys, P hands the screen to `save_picture`. Returns success, stopped (a signal
// or a lost terminal), or terminal_problem with `problem` set.
ExitStatus run_terminal_player(AnimationPlayer& player, int delay_ms, GlyphSet glyphs, const PictureSaver& save_picture,
                               Diagnostic& problem);

} // namespace apcs
