#pragma once

#include "apcs/cli/play_command.h"
#include "apcs/cli/session_command.h"

#include <iosfwd>

namespace apcs {

// Parses the command line (SPEC §1) and runs the chosen command. Returns the exit status:
// 0 success, 1 bad input, 2 bad usage (an unknown option or a bad value, with a one-line reason
// and the usage on `err`), 3 a terminal problem.
// `terminal` runs the interactive session and apcs play in a terminal; without it only headless
// sessions run.
int run_command_line(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                     const TerminalRunner& terminal = {});

} // namespace apcs
