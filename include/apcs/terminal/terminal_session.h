#pragma once

#include "apcs/raster/glyph_mapper.h"
#include "apcs/session/key_event.h"
#include "apcs/session/session.h"

#include <string>
#include <vector>

namespace apcs {

// Runs the session in the terminal: the scripted keys first, as if typed, then the keyboard.
// Every key handled is appended to `recorded`. Returns the exit status: 0 when the session
// ended, 130 when stopped by a signal or a lost terminal, 3 with `problem` set when there is no
// usable terminal.
int run_terminal_session(Session& session, const std::vector<KeyEvent>& scripted, GlyphSet glyphs,
                         std::vector<KeyEvent>& recorded, std::string& problem);

} // namespace apcs
