#include "stop_signals.h"

#include <initializer_list>

namespace apcs {

namespace {

volatile std::sig_atomic_t stop_requested = 0;

// One stop is enough: from the first signal on the others are ignored (sigaction is
// async-signal-safe), so that a hang-up's second SIGHUP cannot cut short the writing of files.
extern "C" void request_stop(int)
{
    stop_requested = 1;
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGINT, &ignore, nullptr);
    sigaction(SIGTERM, &ignore, nullptr);
    sigaction(SIGHUP, &ignore, nullptr);
    sigaction(SIGQUIT, &ignore, nullptr);
}

} // namespace

StopSignals::StopSignals()
{
    stop_requested = 0;
    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &m_old_int);
    sigaction(SIGTERM, &action, &m_old_term);
    sigaction(SIGHUP, &action, &m_old_hup);
    // Ctrl-\ (SIGQUIT) would otherwise end the program with a core and the terminal left raw.
    sigaction(SIGQUIT, &action, &m_old_quit);
}

StopSignals::~StopSignals()
{
    if (stop_requested) {
        // After a stop the program only finishes its files; a second hang-up (the kernel sends one
        // when the terminal's session leader goes) must not cut that short.
        sigset_t finishing;
        sigemptyset(&finishing);
        for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE})
            sigaddset(&finishing, signal);
        sigprocmask(SIG_BLOCK, &finishing, nullptr);
        return;
    }
    sigaction(SIGINT, &m_old_int, nullptr);
    sigaction(SIGTERM, &m_old_term, nullptr);
    sigaction(SIGHUP, &m_old_hup, nullptr);
    sigaction(SIGQUIT, &m_old_quit, nullptr);
}

bool StopSignals::requested() const { return stop_requested != 0; }

void StopSignals::request() { stop_requested = 1; }

} // namespace apcs
