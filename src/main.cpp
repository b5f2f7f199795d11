#include "apcs/base/stopping_signals.h"
#include "apcs/cli/command_line.h"
#include "apcs/formats/unfinished_files.h"
#include "apcs/base/exit_status.h"
#include "apcs/terminal/run_terminal_program.h"

#include <clocale>
#include <csignal>
#include <exception>
#include <iostream>
#include <new>
#include <malloc.h>
#include <unistd.h>

namespace {

// A signal that ends a batch command (the session's terminal handles its own) first removes the
// temporary files being written, then ends the program with exit status 130, as SPEC §1 says of
// every command ended by a signal (not 128 + the signal, as the signal itself would).
extern "C" void end_on_signal(int)
{
    apcs::remove_unfinished_files();
    ::_exit(apcs::to_int(apcs::ExitStatus::stopped));
}

// SIGPIPE from a write of our own into a pipe whose reader has gone (apcs path ... --print | head)
// ends the program quietly with the signal's own status, 141, as GNU tools do; one sent by another
// process (kill -PIPE) is a stop like SIGTERM. Temporary files go either way.
extern "C" void end_on_pipe(int signal, siginfo_t* info, void*)
{
    if (info->si_pid != ::getpid())
        end_on_signal(signal);
    apcs::remove_unfinished_files();
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    sigaction(SIGPIPE, &default_action, nullptr);
    ::raise(SIGPIPE); // delivered as the handler returns
}

void remove_unfinished_files_on_signals()
{
    struct sigaction action {};
    action.sa_handler = end_on_signal;
    sigemptyset(&action.sa_mask);
    for (const int signal : apcs::stopping_signals)
        sigaction(signal, &action, nullptr);
    // A SIGPIPE ignored by whoever started APCS stays ignored: writes then fail with EPIPE.
    struct sigaction pipe_action {};
    sigaction(SIGPIPE, nullptr, &pipe_action);
    if (pipe_action.sa_handler == SIG_IGN)
        return;
    pipe_action.sa_sigaction = end_on_pipe;
    pipe_action.sa_flags = SA_SIGINFO;
    sigemptyset(&pipe_action.sa_mask);
    sigaction(SIGPIPE, &pipe_action, nullptr);
}

} // namespace

int main(int argc, char** argv)
{
    remove_unfinished_files_on_signals();
    // Any exception ends the program here, after unwinding has given the terminal back (the
    // Terminal is owned inside run_terminal_program). Exit status 1, as for bad input or a failed
    // write (SPEC §1 has no status of its own for it): the command did not do what it was asked.
    try {
        // The locale's character set decides the default glyphs and refuses those it cannot show
        // (the session command's terminal_glyphs); curses needs it for wide characters. Only the
        // character set: numbers are written and read with '.' in every locale (SPEC section 1),
        // as the .dat files are, so LC_NUMERIC stays "C" (a German locale's 0,5 would reach the
        // staff, apcs.log and CLI11's reading of --tension 0.5).
        std::setlocale(LC_CTYPE, "");
        // Large buffers (key files, frames, file texts) come and go in a batch run; a fixed mmap
        // threshold hands each back to the system when freed instead of letting glibc keep it in
        // the heap, so peak memory is what is in use at once.
        mallopt(M_MMAP_THRESHOLD, 256 * 1024);
        const apcs::TerminalRunner terminal = apcs::run_terminal_program;
        return static_cast<int>(apcs::run_command_line(argc, argv, std::cout, std::cerr, terminal));
    } catch (const std::bad_alloc&) {
        std::cerr << "apcs: out of memory\n";
    } catch (const std::exception& error) {
        std::cerr << "apcs: internal error: " << error.what() << '\n';
    } catch (...) {
        std::cerr << "apcs: internal error: unknown exception\n";
    }
    return apcs::to_int(apcs::ExitStatus::bad_input);
}
