#pragma once

namespace apcs {

// Exit status of the apcs executable (SPEC §1).
enum class ExitStatus : int {
    success = 0,
    bad_input = 1,
    bad_usage = 2,
    terminal_problem = 3,
    // The session was stopped by Ctrl-C, Ctrl-\ (SIGQUIT), SIGTERM, SIGHUP or a lost terminal (128 + SIGINT, as
    // shells report it); every file written so far is whole.
    stopped = 130,
};

constexpr int to_int(ExitStatus status) { return static_cast<int>(status); }

} // namespace apcs
