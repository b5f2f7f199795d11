#pragma once

#include "apcs/session/session.h"

#include <string_view>

namespace apcs {

// A replay's caption (a ";;" comment of the script) laid over a screen, in reverse video: on the
// message line of graphics mode, on the bottom row of the text console. An empty caption leaves
// the screen as it is.
SessionScreen with_caption(SessionScreen screen, std::string_view caption);

} // namespace apcs
