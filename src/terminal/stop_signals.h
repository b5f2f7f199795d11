#pragma once

#include "apcs/base/stopping_signals.h"

#include <array>
#include <csignal>

namespace apcs {

// While it lives, the stopping signals (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1 …) and SIGPIPE
// ask the program to stop instead of ending it: the terminal is given back and every file finished. One stop is enough: from the
// first signal on the others are ignored. Construction clears any earlier request and installs the
// handler; destruction gives the old handlers back, or, after a stop, blocks these signals (and
// SIGPIPE) for the rest of the program, which only finishes its files.
class StopSignals {
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    // Whether a signal, or request(), asked to stop.
    bool requested() const;
    // A stop without a signal (the terminal gone, its SIGHUP perhaps still on its way).
    void request();

private:
    std::array<struct sigaction, stopping_signals.size() + 1> m_old_actions{};
};

} // namespace apcs
