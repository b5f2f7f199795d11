#pragma once

#include "apcs/formats/diagnostic.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/session/animation_player.h"
#include "apcs/session/exit_status.h"
#include "apcs/session/scene_player.h"

namespace apcs {

// Plays `player` in the terminal (apcs play) as a ScenePlayer (scene_player.h), in the session's
// terminal loop. Returns success, stopped (a signal or a lost terminal), or terminal_problem
// with `problem` set.
ExitStatus run_terminal_player(AnimationPlayer& player, int delay_ms, GlyphSet glyphs, const PictureSaver& save_picture,
                               Diagnostic& problem);

} // namespace apcs
