#pragma once

#include "apcs/formats/numbered_files.h"

#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>

namespace apcs {

// How far a long run of files has come, on standard error when it is a terminal: one line
// rewritten in place, "apcs: writing the in-between files: 1200 of 100000 (1%)", first after
// `quiet_for` (a run of a few files says nothing) and then at most ten times a second; the last
// count ends the line. Ctrl-C still stops the run (every file written stays whole). Off, it says
// nothing at all. One object a run; report() may be called from any thread.
class WriteProgressLine {
public:
    WriteProgressLine(std::ostream& err, bool shown, std::string what,
                      std::chrono::milliseconds quiet_for = std::chrono::milliseconds(500));
    // A line left without its end (a run that failed half-way) is ended, so that the reason
    // printed after it stands on a line of its own.
    ~WriteProgressLine();
    WriteProgressLine(const WriteProgressLine&) = delete;
    WriteProgressLine& operator=(const WriteProgressLine&) = delete;

    // What write_numbered_files calls; empty when off, so that the writers skip it.
    WriteProgress report();

private:
    struct Shared;
    std::shared_ptr<Shared> m_shared;
};

// Whether standard error is a terminal, where WriteProgressLine is shown.
bool standard_error_is_terminal();

} // namespace apcs
