#pragma once

#include "apcs/session/exit_status.h"
#include "apcs/cli/options.h"
#include "apcs/formats/diagnostic.h"
#include "apcs/session/key_event.h"
#include "apcs/session/session.h"

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace apcs {

// The terminal shell of the session, supplied by the executable (the only part linked with
// ncurses); see run_terminal_session. Returns success, stopped, or terminal_problem with
// `problem` set.
using TerminalSessionRunner =
    std::function<ExitStatus(Session&, const std::vector<KeyEvent>& scripted, GlyphSet glyphs,
                             std::vector<KeyEvent>& recorded, Diagnostic& problem)>;

// Runs the session headless: every key of the script, the animation untimed, and the screen after
// each change of step to `out` (a line "--- STEP", then the 80x25 screen, trailing blanks
// removed). Returns the keys handled.
std::vector<KeyEvent> run_headless_session(Session& session, const std::vector<KeyEvent>& keys, GlyphSet glyphs,
                                           std::ostream& out);

// `apcs` with no command: the interactive session in --workdir (default: the current folder).
// With a terminal the session runs there (--keys typed first); without one it needs --keys and
// runs headless; otherwise exit 3.
ExitStatus run_session_command(const CommonOptions& options, const TerminalSessionRunner& terminal, std::ostream& out,
                               std::ostream& err);

} // namespace apcs
