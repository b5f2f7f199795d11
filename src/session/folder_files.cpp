#include "apcs/session/session_files.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/unfinished_files.h"
#include "apcs/formats/inbetween_files.h"

#include <algorithm>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace apcs {

Diagnostic FolderFiles::as_typed(Diagnostic problem) const
{
    const std::filesystem::path named(problem.file);
    const std::filesystem::path relative = named.lexically_relative(m_folder);
    if (!relative.empty() && *relative.begin() != "..")
        problem.file = relative.string();
    return problem;
}

Expected<std::string> FolderFiles::read_text(const std::string& name)
{
    Expected<std::string> text = read_text_file(m_folder / name);
    if (!text)
        return Diagnostic{name, 0, text.error().message};
    return text;
}

Expected<DatFile> SessionFiles::read_dat(const std::string& name, std::size_t minimum_points)
{
    const Expected<std::string> text = read_text(name);
    if (!text)
        return text.error();
    return parse_dat(*text, name, minimum_points);
}

Expected<DatText> SessionFiles::read_dat_text(const std::string& name, std::size_t minimum_points)
{
    Expected<std::string> text = read_text(name);
    if (!text)
        return text.error();
    Expected<DatFile> file = parse_dat(*text, name, minimum_points);
    if (!file)
        return file.error();
    return DatText{std::move(*file), std::move(*text)};
}

bool FolderFiles::exists(const std::string& name) const
{
    std::error_code error;
    return std::filesystem::exists(std::filesystem::symlink_status(m_folder / name, error));
}

bool SessionFiles::lies_in_folder(const std::string& name) const
{
    const std::filesystem::path typed(name);
    return !typed.is_absolute() &&
           std::none_of(typed.begin(), typed.end(), [](const std::filesystem::path& part) { return part == ".."; });
}

bool FolderFiles::lies_in_folder(const std::string& name) const
{
    if (!SessionFiles::lies_in_folder(name))
        return false;
    // Symbolic links on the way are followed: out -> ../elsewhere makes out/way1.dat lie elsewhere.
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::weakly_canonical(m_folder, error);
    const std::filesystem::path file = std::filesystem::weakly_canonical(m_folder / name, error);
    if (error)
        return false;
    return lies_within(file, folder);
}

std::string FolderFiles::name_read(const std::string& name) const
{
    const std::filesystem::path typed(name);
    const std::filesystem::path found = resolve_input_path(m_folder / typed);
    // Only the last part of a name is matched ignoring case: keep what was typed before it.
    return (typed.parent_path() / found.filename()).string();
}

void FolderFiles::protect_key_file(const std::string& name) { m_key_files.protect(m_folder / name); }

Expected<void> FolderFiles::write(const std::string& name, const std::string& content)
{
    if (m_key_files.guards(m_folder / name))
        return Diagnostic{name, 0, "is a key file; key files are never written"};
    const Expected<WriteResult> result = write_file_atomically(
        m_folder / name, content, &m_key_files, m_in_batch ? Durability::at_barrier : Durability::each_file);
    if (!result)
        return Diagnostic{name, 0, result.error().message};
    if (!result->backup.empty() && result->backup.extension() != ".bak")
        log("kept the old " + name + " as " + result->backup.filename().string() + ", since its .bak is a key file");
    return ok;
}

Expected<std::vector<std::string>> FolderFiles::write_inbetweens(const FrameSequence& frames, const Graphic& structure)
{
    const Expected<std::vector<std::filesystem::path>> written =
        write_inbetween_files(frames, structure, m_folder, m_key_files);
    if (!written)
        return as_typed(written.error());
    std::vector<std::string> names;
    for (const std::filesystem::path& path : *written)
        names.push_back(path.filename().string());
    return names;
}

std::vector<std::string> FolderFiles::earlier_inbetweens(std::size_t written_count) const
{
    return inbetweens_beyond(m_folder, written_count);
}

Expected<void> FolderFiles::end_batch()
{
    m_in_batch = false;
    return flush_file_system(m_folder);
}

FolderFiles::~FolderFiles()
{
    if (m_in_batch)
        [[maybe_unused]] const Expected<void> ignored = end_batch();
}

void FolderFiles::log(const std::string& line)
{
    // The log is the session's own record, appended line by line so that it survives a stop. Only
    // a regular file is appended to: a FIFO there would block the session, a link lead outside.
    // Not once a stop has begun: apcs grade's replays log in a folder the stop is removing.
    const std::string text = line + '\n';
    make_unless_stopping([&] {
        const int log = ::open((m_folder / "apcs.log").c_str(),
                               O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
        if (log < 0)
            return;
        struct stat status {};
        if (::fstat(log, &status) == 0 && S_ISREG(status.st_mode)) {
            [[maybe_unused]] const ssize_t written = ::write(log, text.data(), text.size());
        }
        ::close(log);
    });
}

} // namespace apcs
