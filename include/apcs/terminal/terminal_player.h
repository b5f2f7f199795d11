#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/pixel_picture.h"
#include "apcs/session/animation_player.h"
#include "apcs/session/exit_status.h"
#include "apcs/session/scene_player.h"

namespace apcs {

// Plays `player` in the terminal (apcs play) as a ScenePlayer (scene_player.h), in the session's
// terminal loop, the drawing area as a picture where `pixels` (--pixels) finds one shown.
// Returns success or stopped (a signal or a lost terminal), or why there is no usable terminal
// ("apcs: PROBLEM").
Expected<ExitStatus> run_terminal_player(AnimationPlayer& player, int delay_ms, GlyphSet glyphs, PixelChoice pixels,
                                         const PictureSaver& save_picture);

} // namespace apcs
