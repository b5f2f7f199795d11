#pragma once

#include <csignal>

namespace apcs {

// While it lives, SIGINT, SIGTERM, SIGHUP and SIGQUIT (Ctrl-\) ask the program to stop instead of
// ending it: the terminal is given back and every file finished. One stop is enough: from the
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
    struct sigaction m_old_int {};
    struct sigaction m_old_term {};
    struct sigaction m_old_hup {};
    struct sigaction m_old_quit {};
};

} // namespace apcs
