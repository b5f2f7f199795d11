#pragma once

#include <array>
#include <csignal>

namespace apcs {

// The signals that stop APCS (SPEC §1): the terminal given back, unfinished files removed, exit
// status 130. Ctrl-C, kill, a hang-up, Ctrl-\, and the other signals whose default action ends a
// program silently (SIGUSR1, SIGUSR2, timers, the CPU limit), which would leave the terminal raw.
// Not here: SIGPIPE, which ends a --print into a closed pipe quietly as GNU tools do (and is a
// stop when another process sends it, main.cpp; always with a terminal, stop_signals.cpp); SIGTSTP,
// which ncurses handles (Ctrl-Z suspends with the terminal restored, fg redraws); faults.
inline constexpr std::array stopping_signals{SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1,
                                             SIGUSR2, SIGALRM, SIGVTALRM, SIGXCPU};

} // namespace apcs
