#include "stop_signals.h"

#include <array>
#include <cstddef>

namespace apcs {

namespace {

volatile std::sig_atomic_t stop_requested = 0;

// With a terminal, SIGPIPE stops the program too, whoever sent it: the screen goes to a terminal,
// never a pipe, and the terminal must be given back (batch commands end quietly on it instead).
constexpr std::array<int, stopping_signals.size() + 1> terminal_stopping_signals = [] {
    std::array<int, stopping_signals.size() + 1> signals{};
    for (std::size_t i = 0; i < stopping_signals.size(); ++i)
        signals[i] = stopping_signals[i];
    signals.back() = SIGPIPE;
    return signals;
}();

// One stop is enough: from the first signal on the others are ignored (sigaction is
// async-signal-safe), so that a hang-up's second SIGHUP cannot cut short the writing of files.
extern "C" void request_stop(int)
{
    stop_requested = 1;
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    for (const int signal : terminal_stopping_signals)
        sigaction(signal, &ignore, nullptr);
}

} // namespace

StopSignals::StopSignals()
{
    stop_requested = 0;
    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    // Ctrl-\ (SIGQUIT) would otherwise end the program with a core, SIGUSR1 at once: the terminal
    // left raw either way.
    for (std::size_t i = 0; i < terminal_stopping_signals.size(); ++i)
        sigaction(terminal_stopping_signals[i], &action, &m_old_actions[i]);
}

StopSignals::~StopSignals()
{
    if (stop_requested) {
        // After a stop the program only finishes its files; a second hang-up (the kernel sends one
        // when the terminal's session leader goes) must not cut that short.
        sigset_t finishing;
        sigemptyset(&finishing);
        for (const int signal : terminal_stopping_signals)
            sigaddset(&finishing, signal);
        sigprocmask(SIG_BLOCK, &finishing, nullptr);
        return;
    }
    for (std::size_t i = 0; i < terminal_stopping_signals.size(); ++i)
        sigaction(terminal_stopping_signals[i], &m_old_actions[i], nullptr);
}

bool StopSignals::requested() const { return stop_requested != 0; }

void StopSignals::request() { stop_requested = 1; }

} // namespace apcs
