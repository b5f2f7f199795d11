// addpoint.c and split.c (SPEC §5.1, §5.2): equal point counts, then one path file per point,
// written a batch at a time so that the shell can read keys between batches.
#include "apcs/session/session.h"

#include "apcs/formats/path_files.h"

#include <algorithm>

namespace apcs {

namespace {

// Path files per work(): small enough that a key is read within a few milliseconds even on a
// slow disk, large enough that reading keys costs nothing next to the writing.
constexpr std::size_t split_batch_files = 64;

} // namespace

void Session::add_points_and_split()
{
    m_keys = equalise_key_frames(m_key_frames[0], m_key_frames[1]);
    m_point_count = m_keys.key1.point_count();
    m_split = Split{m_keys.key1.all_points(), m_keys.key2.all_points(), 0};
    m_files.begin_batch();
    m_step = TextStep{SessionPhase::splitting};
    // Keys of up to a batch of points are split at once, as in the thesis.
    work();
}

void Session::work()
{
    if (!m_split)
        return;
    Split& split = *m_split;
    const std::size_t total = std::min(split.key1.size(), split.key2.size());
    const std::size_t batch_end = std::min(total, split.written + split_batch_files);
    while (split.written < batch_end) {
        const std::size_t index = split.written;
        const NamedText file = split_path_file(index + 1, split.key1[index], split.key2[index]);
        if (auto problem = write_file(file.name, file.content)) {
            close_split();
            return ask_again(SessionPhase::ask_key2, problem->to_string());
        }
        record_written(file.name);
        ++split.written;
    }
    if (split.written == total)
        finish_split();
}

void Session::finish_split()
{
    if (const std::optional<Diagnostic> problem = close_split())
        return ask_again(SessionPhase::ask_key2, problem->to_string());
    m_files.log("added points: both keys have " + std::to_string(m_point_count) + " points in " +
                std::to_string(m_keys.key1.parts.size()) + " parts; wrote ani1.dat … " + path_file_name(m_point_count));
    go_to(SessionPhase::ask_view);
}

// Esc while splitting: the files written stay (each whole), and KEY2 is asked again.
void Session::stop_split(const std::string&)
{
    const std::size_t written = m_split->written;
    const std::size_t total = std::min(m_split->key1.size(), m_split->key2.size());
    const std::optional<Diagnostic> problem = close_split();
    const std::string files = written == 0 ? std::string("no path file")
                                           : "ani1.dat … " + path_file_name(written) + " (" + std::to_string(written) +
                                                 " of " + std::to_string(total) + ")";
    m_files.log("split stopped: " + files + " written");
    ask_again(SessionPhase::ask_key2, problem ? problem->to_string()
                                              : "Split stopped: " + files + " written, none half-written");
}

std::optional<Diagnostic> Session::close_split()
{
    m_split.reset();
    std::optional<Diagnostic> problem = m_files.end_batch();
    if (problem)
        m_write_problem = problem;
    return problem;
}

std::string Session::split_progress() const
{
    const std::size_t total = std::min(m_split->key1.size(), m_split->key2.size());
    const std::string last = m_split->written == 0 ? std::string("nothing") : path_file_name(m_split->written);
    return "Splitting: " + last + " of " + std::to_string(total) + " written - Esc stops, Ctrl-C ends APCS";
}

} // namespace apcs
