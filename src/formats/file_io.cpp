#include "apcs/formats/file_io.h"

#include "apcs/animation/memory_budget.h"
#include "apcs/formats/text_fields.h"
#include "apcs/formats/text_lines.h"
#include "posix_files.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <utility>
#include <vector>

namespace apcs {

namespace fs = std::filesystem;
using namespace posix_files;

namespace {

Diagnostic too_large(const std::string& shown, std::uintmax_t bytes, std::uintmax_t most_bytes)
{
    return Diagnostic{shown, 0, "is " + std::to_string(bytes) + " bytes; expected at most " + std::to_string(most_bytes) +
                                    " bytes (" + memory::byte_count_text(most_bytes) + ")"};
}

// No text APCS reads holds a NUL byte: a binary file is refused at the first one, before the rest
// of it is read. `lines_before` counts the LFs before `chunk`, for the line number.
Expected<void> refuse_nul_byte(const std::string& shown, std::size_t lines_before, std::string_view chunk)
{
    const std::size_t nul = chunk.find('\0');
    if (nul == std::string_view::npos)
        return ok;
    const auto lines = lines_before + static_cast<std::size_t>(std::count(chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(nul), '\n'));
    return Diagnostic{shown, 1 + static_cast<int>(lines), "NUL byte; expected a text file"};
}

} // namespace

Expected<fs::path> find_input_path(const fs::path& name)
{
    std::error_code error;
    if (fs::exists(name, error))
        return name;
    const fs::path folder = name.has_parent_path() ? name.parent_path() : fs::path(".");
    const std::string wanted = name.filename().string();
    std::vector<std::string> matches;
    for (fs::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error))
        if (equals_ignoring_case(entry->path().filename().string(), wanted))
            matches.push_back(entry->path().filename().string());
    if (matches.empty())
        return name;
    if (matches.size() == 1)
        return name.has_parent_path() ? folder / matches[0] : fs::path(matches[0]);
    // The folder's order is no choice the user made: naming them all lets them type the one meant.
    std::sort(matches.begin(), matches.end());
    std::string listed;
    for (const std::string& match : matches)
        listed += (listed.empty() ? "" : match == matches.back() ? " and " : ", ") + match;
    return Diagnostic{name.string(), 0, "is ambiguous: " + listed + " differ only in case; expected the exact name"};
}

fs::path resolve_input_path(const fs::path& name)
{
    const Expected<fs::path> found = find_input_path(name);
    return found ? *found : name;
}

Expected<void> read_text_pieces(const fs::path& name, const TextPieceSink& consume, std::uintmax_t most_bytes,
                                std::uintmax_t* file_size)
{
    const std::string shown = name.string();
    const Expected<fs::path> found = find_input_path(name);
    if (!found)
        return Diagnostic{shown, 0, found.error().message};
    const fs::path& path = *found;
    // Only regular files are read: a FIFO would wait forever for a writer, a device could be read
    // without end. stat() first, so that such a file is never even opened; O_NONBLOCK and the
    // fstat() after the open cover a file swapped for a FIFO in between.
    struct stat status {};
    if (::stat(path.c_str(), &status) == 0) {
        if (S_ISDIR(status.st_mode))
            return Diagnostic{shown, 0, "is a directory; expected a file"};
        if (!S_ISREG(status.st_mode))
            return Diagnostic{shown, 0, not_regular(status.st_mode) + "; expected a file"};
    }
    FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY));
    if (file.get() < 0)
        return Diagnostic{shown, 0, "cannot open: " + system_reason(errno)};
    if (::fstat(file.get(), &status) != 0)
        return Diagnostic{shown, 0, "cannot read: " + system_reason(errno)};
    if (!S_ISREG(status.st_mode))
        return Diagnostic{shown, 0, not_regular(status.st_mode) + "; expected a file"};
    // Refused by its size before a byte is read, so a huge file costs no time and no memory.
    if (static_cast<std::uintmax_t>(status.st_size) > most_bytes)
        return too_large(shown, static_cast<std::uintmax_t>(status.st_size), most_bytes);
    if (file_size != nullptr)
        *file_size = static_cast<std::uintmax_t>(status.st_size);
    std::uintmax_t total = 0;
    std::size_t lines = 0;
    char buffer[1 << 16];
    while (true) {
        const ssize_t got = ::read(file.get(), buffer, sizeof buffer);
        if (got < 0) {
            if (errno == EINTR)
                continue;
            return Diagnostic{shown, 0, "cannot read: " + system_reason(errno)};
        }
        if (got == 0)
            return ok;
        const std::string_view chunk(buffer, static_cast<std::size_t>(got));
        if (auto outcome = refuse_nul_byte(shown, lines, chunk); !outcome)
            return outcome.error();
        // A file that grew while it was read.
        if (total + chunk.size() > most_bytes)
            return too_large(shown, total + chunk.size(), most_bytes);
        total += chunk.size();
        lines += static_cast<std::size_t>(std::count(chunk.begin(), chunk.end(), '\n'));
        if (auto outcome = consume(chunk); !outcome)
            return outcome.error();
    }
}

Expected<std::string> read_text_file(const fs::path& name, std::uintmax_t most_bytes)
{
    std::string content;
    std::uintmax_t size = 0;
    const auto append = [&content, &size](std::string_view chunk) -> Expected<void> {
        if (content.empty())
            content.reserve(static_cast<std::size_t>(size));
        content.append(chunk);
        return ok;
    };
    if (auto outcome = read_text_pieces(name, append, most_bytes, &size); !outcome)
        return outcome.error();
    return content;
}

namespace {

// The limits of a text file checked on a stream as it is read, since a stream has no size to
// refuse up front: a line over max_text_line_bytes is refused once that many bytes of it have come
// (`yes 1 | tr -d '\n'` never ends one), and for a .dat file more data lines than max_dat_points
// (and a count line) at the first past them, so that a stream costs no more memory than the
// largest file. Scenes and key scripts read from a stream have the line limit only.
class StreamLimits {
public:
    StreamLimits(std::string shown, bool dat_points)
        : m_shown(std::move(shown))
        , m_dat_points(dat_points)
    {
    }

    Expected<void> operator()(std::string_view chunk)
    {
        for (const char byte : chunk) {
            if (byte == '\n' || byte == '\r') {
                end_line();
                continue;
            }
            if (byte == ';' || byte == '#')
                m_in_comment = true;
            else if (!m_in_comment && byte != ' ' && byte != '\t')
                m_has_data = true;
            if (++m_line_bytes > max_text_line_bytes)
                return Diagnostic{m_shown, m_line + 1,
                                  "line is more than " + std::to_string(max_text_line_bytes) +
                                      " bytes long; expected at most " + std::to_string(max_text_line_bytes)};
        }
        if (m_dat_points && m_data_lines > max_dat_points + 1)
            return Diagnostic{m_shown, m_line,
                              "more than " + std::to_string(max_dat_points) + " points; expected at most that many"};
        return ok;
    }

private:
    void end_line()
    {
        ++m_line;
        m_data_lines += m_has_data ? 1 : 0;
        m_line_bytes = 0;
        m_in_comment = false;
        m_has_data = false;
    }

    std::string m_shown;
    bool m_dat_points;
    int m_line = 0; // lines ended so far (at most 2^30, the bytes a stream may have)
    std::size_t m_line_bytes = 0;
    std::size_t m_data_lines = 0;
    bool m_in_comment = false;
    bool m_has_data = false;
};

Expected<std::string> read_pipe_to_end(int descriptor, const std::string& shown, std::uintmax_t most_bytes,
                                       const TextPieceSink& check = {});

// A .dat file's text and the name its messages use; "-" is standard input, read like a keystroke
// script (a pipe, once, to its end) within a file's limits (StreamLimits).
Expected<std::pair<std::string, std::string>> dat_text(const fs::path& name)
{
    Expected<std::string> text = name == "-" ? read_pipe_to_end(STDIN_FILENO, "standard input", max_input_bytes,
                                                                StreamLimits("standard input", true))
                                             : read_text_file(name);
    if (!text)
        return text.error();
    return std::pair{std::move(*text), name == "-" ? std::string("standard input") : name.string()};
}

} // namespace

Expected<DatFile> read_dat_file(const fs::path& name, std::size_t minimum_points)
{
    const Expected<std::pair<std::string, std::string>> text = dat_text(name);
    if (!text)
        return text.error();
    return parse_dat(text->first, text->second, minimum_points);
}

Expected<Graphic> read_key_frame(const fs::path& name)
{
    if (name == "-") {
        const Expected<std::pair<std::string, std::string>> text = dat_text(name);
        if (!text)
            return text.error();
        return parse_key_frame(text->first, text->second);
    }
    // Read twice, a block at a time, never whole: first its lines are counted (to size the
    // points once), then they are parsed as they come. A large key costs its points, not its text.
    std::size_t lines = 1;
    const auto count_lines = [&lines](std::string_view chunk) -> Expected<void> {
        lines += static_cast<std::size_t>(std::count(chunk.begin(), chunk.end(), '\n'));
        return ok;
    };
    if (auto outcome = read_text_pieces(name, count_lines); !outcome)
        return outcome.error();
    return parse_key_frame_pieces(name.string(), lines,
                                  [&name](const TextPieceSink& sink) { return read_text_pieces(name, sink); });
}

namespace {

// Everything a pipe holds until its writer closes it, at most `most_bytes`; each chunk first
// passes `check`, when given, whose problem ends the reading.
Expected<std::string> read_pipe_to_end(int descriptor, const std::string& shown, std::uintmax_t most_bytes,
                                       const TextPieceSink& check)
{
    std::string content;
    std::size_t lines = 0;
    char buffer[1 << 16];
    while (true) {
        const ssize_t got = ::read(descriptor, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            return Diagnostic{shown, 0, "cannot read: " + system_reason(errno)};
        if (got == 0)
            return content;
        // A stream has no size to refuse up front: it is refused at its first NUL, as a file is.
        const std::string_view chunk(buffer, static_cast<std::size_t>(got));
        if (auto outcome = refuse_nul_byte(shown, lines, chunk); !outcome)
            return outcome.error();
        if (content.size() + chunk.size() > most_bytes)
            return too_large(shown, content.size() + chunk.size(), most_bytes);
        if (check)
            if (auto outcome = check(chunk); !outcome)
                return outcome.error();
        lines += static_cast<std::size_t>(std::count(chunk.begin(), chunk.end(), '\n'));
        content.append(chunk);
    }
}

} // namespace

Expected<std::string> read_script_text(const fs::path& name, std::uintmax_t most_bytes)
{
    if (name == "-")
        return read_pipe_to_end(STDIN_FILENO, "standard input", most_bytes, StreamLimits("standard input", false));
    struct stat status {};
    if (::stat(name.c_str(), &status) != 0 || !S_ISFIFO(status.st_mode))
        return read_text_file(name, most_bytes);
    FileDescriptor pipe(::open(name.c_str(), O_RDONLY | O_CLOEXEC));
    if (pipe.get() < 0)
        return Diagnostic{name.string(), 0, "cannot open: " + system_reason(errno)};
    return read_pipe_to_end(pipe.get(), name.string(), most_bytes, StreamLimits(name.string(), false));
}

} // namespace apcs
