#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/cli/options.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/base/exit_status.h"
#include "apcs/cli/terminal_runner.h"
#include "apcs/playback/animation_player.h"

#include <filesystem>
#include <iosfwd>
#include <string>

namespace apcs {

// P in apcs play: the screen as apcs001.png … (the first name free in the current folder), as the
// monitor showed it; "wrote apcs001.png", or what went wrong.
std::string save_screen_picture(const GraphicsScreen& screen);

struct PlayRequest {
    std::filesystem::path scene;
    bool tree = false; // --tree: print the data-structure tree (fig. 3.3.2) only
};

// `apcs play SCENE` (SPEC §8.3): reads the scene (exit 1 with FILE:LINE on a problem) and prints its
// tree (--tree), its frames' numbers (--print), writes frm000.dat … (--out), the overlay (--png,
// --png-raw, --svg) and the animation (--gif); with none of these it plays on the terminal (exit 3
// without one).
ExitStatus run_play_command(const PlayRequest& request, const CommonOptions& options,
                            const TerminalRunner& terminal, std::ostream& out, std::ostream& err);

// "frm000.dat" … "frm060.dat": frame `frame` of a scene whose last frame is `last_frame`, the
// number as wide as the last needs, at least 3 digits.
std::string scene_frame_file_name(int frame, int last_frame);

} // namespace apcs
