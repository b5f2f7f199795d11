#include "apcs/base/stopping_signals.h"
#include "apcs/cli/command_line.h"
#include "apcs/formats/unfinished_files.h"
#include "apcs/base/exit_status.h"
#include "apcs/terminal/terminal_session.h"

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

void remove_unfinished_files_on_signals()
{
    struct sigaction action {};
    action.sa_handler = end_on_signal;
    sigemptyset(&action.sa_mask);
    for (const int signal : apcs::stopping_signals)
        sigaction(signal, &action, nullptr);
}

} // namespace

int main(int argc, char** argv)
{
    remove_unfinished_files_on_signals();
    // Any exception ends the program here, after unwinding has given the terminal back (the
    // Terminal is owned inside run_terminal_program). Exit status 1, as for bad input or a failed
    // write (SPEC §1 has no status of its own for it): the command did not do what it was asked.
    try {
        // The locale decides the default glyphs and refuses those it cannot show (the session
        // command's terminal_glyphs); curses needs it for wide characters.
        std::setlocale(LC_ALL, "");
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
