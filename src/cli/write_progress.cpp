#include "apcs/cli/write_progress.h"

#include <mutex>
#include <utility>
#include <ostream>
#include <unistd.h>

namespace apcs {

struct WriteProgressLine::Shared {
    Shared(std::ostream& stream, std::string text, std::chrono::steady_clock::time_point quiet)
        : err(stream)
        , what(std::move(text))
        , quiet_until(quiet)
    {
    }

    std::ostream& err;
    std::string what;
    std::chrono::steady_clock::time_point quiet_until;
    std::mutex mutex;
    std::chrono::steady_clock::time_point last_shown{};
    bool line_open = false;

    void report(std::size_t written, std::size_t count)
    {
        const std::lock_guard lock(mutex);
        const auto now = std::chrono::steady_clock::now();
        const bool last = written == count;
        if (now < quiet_until || (!last && now - last_shown < std::chrono::milliseconds(100)))
            return;
        if (last && !line_open)
            return; // a run that ended while quiet needs no line
        last_shown = now;
        err << "\rapcs: writing " << what << ": " << written << " of " << count << " (" << written * 100 / count
            << "%)" << (last ? "\n" : "") << std::flush;
        line_open = !last;
    }
};

WriteProgressLine::WriteProgressLine(std::ostream& err, bool shown, std::string what,
                                     std::chrono::milliseconds quiet_for)
{
    if (shown)
        m_shared = std::make_shared<Shared>(err, std::move(what), std::chrono::steady_clock::now() + quiet_for);
}

WriteProgressLine::~WriteProgressLine()
{
    if (m_shared && m_shared->line_open)
        m_shared->err << '\n' << std::flush;
}

WriteProgress WriteProgressLine::report()
{
    if (!m_shared)
        return {};
    return [shared = m_shared](std::size_t written, std::size_t count) { shared->report(written, count); };
}

bool standard_error_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

} // namespace apcs
