#include "apcs/formats/file_io.h"

#include "apcs/formats/unfinished_files.h"
#include "posix_files.h"

#include <algorithm>
#include <cerrno>
#include <fcntl.h>
#include <optional>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <utility>

namespace apcs {

namespace fs = std::filesystem;
using namespace posix_files;

namespace {

// NAME.bak is replaced by the old file only when it is a writable regular file or absent: a FIFO, a
// link, a directory or a read-only file there is the user's, and is left as it is.
Expected<void> check_backup_replaceable(const fs::path& backup, const std::string& shown,
                                        const std::string& shown_backup)
{
    struct stat status {};
    if (backup.empty() || ::lstat(backup.c_str(), &status) != 0)
        return ok;
    const std::string cannot = "cannot keep the old file as " + shown_backup + ": it ";
    if (S_ISLNK(status.st_mode))
        return Diagnostic{shown, 0, cannot + "is a symbolic link; a backup replaces only a regular file"};
    if (S_ISDIR(status.st_mode))
        return Diagnostic{shown, 0, cannot + "is a directory; a backup replaces only a regular file"};
    if (!S_ISREG(status.st_mode))
        return Diagnostic{shown, 0, cannot + not_regular(status.st_mode) + "; a backup replaces only a regular file"};
    if (is_read_only(backup, status))
        return Diagnostic{shown, 0, cannot + "is read-only (mode " + octal_mode(status.st_mode) + "); not replaced"};
    return ok;
}

// The mkstemp pattern of the hidden temporary file for `name` in `folder`: ".NAME.XXXXXX", with
// NAME cut short (at a UTF-8 character boundary) when the whole would pass the folder's longest
// name, so that every name the file system accepts can be written; mkstemp keeps it unique.
std::string temporary_name_for(const fs::path& folder, const std::string& name)
{
    constexpr std::string_view dot = ".";
    constexpr std::string_view unique_tail = ".XXXXXX";
    const long folder_limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
    const std::size_t longest = folder_limit > 0 ? static_cast<std::size_t>(folder_limit) : 255;
    std::size_t kept = name.size();
    if (dot.size() + kept + unique_tail.size() > longest) {
        kept = longest - dot.size() - unique_tail.size();
        while (kept > 0 && (static_cast<unsigned char>(name[kept]) & 0xC0) == 0x80)
            --kept;
    }
    return std::string(dot) + name.substr(0, kept) + std::string(unique_tail);
}

} // namespace

fs::path backup_path_for(const fs::path& target, const KeyFileGuard* inputs)
{
    fs::path backup = target;
    backup.replace_extension(".bak");
    // A .bak file being replaced keeps its predecessor under NAME.bak.bak, never under itself.
    if (backup == target)
        backup += ".bak";
    if (inputs == nullptr || !inputs->guards(backup))
        return backup;
    for (int number = 1; number <= 99; ++number) {
        fs::path numbered = target;
        numbered.replace_extension(std::string(number < 10 ? ".b0" : ".b") + std::to_string(number));
        std::error_code error;
        if (!inputs->guards(numbered) && (number == 99 || !fs::exists(fs::symlink_status(numbered, error))))
            return numbered;
    }
    return {}; // .bak and .b01 … .b99 are all inputs: there is nowhere to keep the old file
}

bool lies_within(const fs::path& file, const fs::path& folder)
{
    const fs::path relative = file.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

Expected<void> check_link_stays_in_folder(const fs::path& output)
{
    struct stat status {};
    if (::lstat(output.c_str(), &status) != 0 || !S_ISLNK(status.st_mode))
        return ok;
    // Followed to its end, so that a chain of links is judged by the file it reaches; the link's
    // own folder is judged the same way, so that a folder reached through a link still counts.
    std::error_code folder_error;
    std::error_code file_error;
    const fs::path folder = fs::weakly_canonical(output.has_parent_path() ? output.parent_path() : fs::path("."), folder_error);
    const fs::path reached = fs::weakly_canonical(output, file_error);
    if (!folder_error && !file_error && lies_within(reached, folder))
        return ok;
    std::error_code link_error;
    const fs::path named = fs::read_symlink(output, link_error);
    return Diagnostic{output.string(), 0,
                      "is a symbolic link to " + (link_error ? std::string("a file") : named.string()) +
                          ", which leads out of its folder (to " + (file_error ? std::string("a file elsewhere") : reached.string()) +
                          "); APCS writes through a link only to a file in the link's folder or below it"};
}

namespace {

// A file write_file_atomically may replace: the regular file `requested` names (through a
// symbolic link), or a name not taken yet.
struct ReplaceableTarget {
    fs::path path;
    bool exists = false;
    struct stat status {};
};

Expected<ReplaceableTarget> replaceable_target(const fs::path& requested, const std::string& shown)
{
    // Only regular files are ever replaced. A symbolic link is written through to the file it
    // names (replaced in its own folder; the link stays) when that is a regular file in the link's
    // folder or below it; a device, a FIFO, a socket or a directory, named or linked to, and a
    // file elsewhere (ln -s ../victim/passwd w/my.keys, worst as root) are refused and left as
    // they are.
    ReplaceableTarget target{requested, false, {}};
    if (::lstat(requested.c_str(), &target.status) != 0)
        return target;
    if (S_ISLNK(target.status.st_mode)) {
        std::error_code error;
        const fs::path named = fs::read_symlink(requested, error);
        const std::string link_to = "is a symbolic link to " + (error ? std::string("a file") : named.string());
        if (::stat(requested.c_str(), &target.status) != 0)
            return Diagnostic{shown, 0, link_to + ", which does not exist (" + system_reason(errno) + "); APCS writes only regular files"};
        if (!S_ISREG(target.status.st_mode))
            return Diagnostic{shown, 0, link_to + ", which " + not_regular(target.status.st_mode) + "; APCS writes only regular files"};
        target.path = fs::canonical(requested, error);
        if (error)
            return Diagnostic{shown, 0, link_to + ", which cannot be followed: " + error.message()};
        if (Expected<void> stays = check_link_stays_in_folder(requested); !stays)
            return Diagnostic{shown, 0, stays.error().message};
    } else if (S_ISDIR(target.status.st_mode)) {
        return Diagnostic{shown, 0, "is a directory; cannot write a file there"};
    } else if (!S_ISREG(target.status.st_mode)) {
        return Diagnostic{shown, 0, not_regular(target.status.st_mode) + "; APCS writes only regular files"};
    }
    target.exists = true;
    return target;
}

// The new content of a file, taken chunk by chunk. While it equals the old file's it is only
// compared; at the first difference the temporary file is made and the equal part copied into it
// from the old file. So content that does not change writes nothing, and no whole file is ever
// held in memory.
class Replacement {
public:
    // `shown_folder`: the target's folder as messages name it.
    Replacement(const ReplaceableTarget& target, std::string shown, fs::path shown_folder, const KeyFileGuard* inputs)
        : m_target(target)
        , m_shown(std::move(shown))
        , m_shown_folder(std::move(shown_folder))
        , m_inputs(inputs)
        , m_old(target.exists ? ::open(target.path.c_str(), O_RDONLY | O_CLOEXEC) : -1)
        , m_differs(!target.exists || m_old.get() < 0)
    {
    }
    Replacement(const Replacement&) = delete;
    Replacement& operator=(const Replacement&) = delete;
    ~Replacement()
    {
        if (!m_temporary.empty()) {
            m_file.close();
            ::unlinkat(m_folder.get(), m_temporary.c_str(), 0);
        }
    }

    bool add(std::string_view chunk)
    {
        if (!m_outcome)
            return false;
        if (!m_differs) {
            if (old_continues_with(chunk)) {
                m_same += chunk.size();
                return true;
            }
            m_differs = true;
        }
        if (m_temporary.empty() && !start_temporary())
            return false;
        m_size += chunk.size();
        return write_all(m_file.get(), chunk) || abandon("cannot write");
    }

    Expected<WriteResult> finish(Durability durability)
    {
        if (!m_outcome)
            return m_outcome.error();
        if (!m_differs && static_cast<std::uintmax_t>(m_target.status.st_size) == m_same)
            return WriteResult{WriteOutcome::unchanged, {}};
        WriteResult result{m_target.exists ? WriteOutcome::replaced : WriteOutcome::created, {}};
        if ((m_temporary.empty() && !start_temporary()) || !complete_temporary(durability) ||
            (m_target.exists && !keep_old_file(result.backup)))
            return m_outcome.error();
        if (::renameat(m_folder.get(), m_temporary.c_str(), m_folder.get(), m_target.path.filename().c_str()) != 0) {
            abandon("cannot replace the file");
            return m_outcome.error();
        }
        m_temporary.clear();
        m_unfinished.reset();
        return result;
    }

private:
    // Whether the old file's next bytes are `chunk`; reads them in pieces, never the whole file.
    bool old_continues_with(std::string_view chunk)
    {
        if (static_cast<std::uintmax_t>(m_target.status.st_size) < m_same + chunk.size())
            return false;
        char buffer[1 << 16];
        while (!chunk.empty()) {
            const ssize_t got = ::read(m_old.get(), buffer, std::min(sizeof buffer, chunk.size()));
            if (got < 0 && errno == EINTR)
                continue;
            if (got <= 0 || std::memcmp(buffer, chunk.data(), static_cast<std::size_t>(got)) != 0)
                return false;
            chunk.remove_prefix(static_cast<std::size_t>(got));
        }
        return true;
    }

    bool start_temporary()
    {
        if (m_target.exists && is_read_only(m_target.path, m_target.status))
            return refuse("is read-only (mode " + octal_mode(m_target.status.st_mode) + "); not replaced");
        if (m_target.exists) {
            const fs::path backup = backup_path_for(m_target.path, m_inputs);
            m_outcome = check_backup_replaceable(backup, m_shown, shown_beside(backup));
            if (!m_outcome)
                return false;
        }
        const fs::path folder = m_target.path.has_parent_path() ? m_target.path.parent_path() : fs::path(".");
        // The temporary file is made, renamed and removed in the folder open here, not by its
        // path: a folder renamed or moved while the file is written still has it renamed or
        // removed, never left behind as .NAME.XXXXXX.
        m_folder.reset(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
        if (m_folder.get() < 0)
            return refuse("cannot create a temporary file in " + shown_folder() + ": " + system_reason(errno));
        std::string temporary = temporary_name_for(folder, m_target.path.filename().string());
        // Known from its making until it is renamed or removed: a signal meanwhile removes it.
        const int descriptor = create_unfinished_file(m_folder.get(), temporary, m_unfinished);
        if (descriptor < 0)
            return refuse("cannot create a temporary file in " + shown_folder() + ": " + system_reason(errno));
        m_file.reset(descriptor);
        m_temporary = std::move(temporary);
        return copy_same_part();
    }

    // The temporary file's content on its way to the disk, its owner and mode those of the file it
    // replaces, and closed.
    bool complete_temporary(Durability durability)
    {
        if (durability == Durability::each_file && ::fsync(m_file.get()) != 0)
            return abandon("cannot flush to disk");
        // At a barrier later: a large file's writeback starts now, while the next files are made,
        // so the barrier finds little left to wait for (12 in-betweens of 6 MB: 25 → 3 ms). Not
        // for small files: 10^5 of them (a split) would each cost a call and a small disk write.
        if (durability == Durability::at_barrier && m_same + m_size >= (std::uintmax_t{1} << 20))
            ::sync_file_range(m_file.get(), 0, 0, SYNC_FILE_RANGE_WRITE);
        if (m_target.exists && (m_target.status.st_uid != ::geteuid() || m_target.status.st_gid != ::getegid())) {
            // Allowed to root, and to the owner for a group of theirs; otherwise the file becomes
            // the user's, as any new file would.
            [[maybe_unused]] const int ignored = ::fchown(m_file.get(), m_target.status.st_uid, m_target.status.st_gid);
        }
        // A new file is 0644; a replaced one keeps its mode.
        const mode_t mode = m_target.exists ? (m_target.status.st_mode & 07777) : 0644;
        if (::fchmod(m_file.get(), mode) != 0)
            return abandon("cannot set permissions");
        if (m_file.close() != 0)
            return abandon("cannot close");
        return true;
    }

    // The part of the old file the new content began with, copied into the temporary file.
    bool copy_same_part()
    {
        char buffer[1 << 16];
        std::uintmax_t copied = 0;
        while (copied < m_same) {
            const ssize_t got = ::pread(m_old.get(), buffer, static_cast<std::size_t>(std::min<std::uintmax_t>(sizeof buffer, m_same - copied)),
                                        static_cast<off_t>(copied));
            if (got < 0 && errno == EINTR)
                continue;
            if (got <= 0 || !write_all(m_file.get(), {buffer, static_cast<std::size_t>(got)}))
                return abandon("cannot write");
            copied += static_cast<std::uintmax_t>(got);
        }
        m_old.close();
        return true;
    }

    // A hard link keeps the old content as .bak while the target itself stays in place until the
    // rename replaces it, so no moment exists without the user's file.
    bool keep_old_file(fs::path& kept)
    {
        const fs::path backup = backup_path_for(m_target.path, m_inputs);
        if (backup.empty())
            return refuse("cannot keep the old file: its .bak and .b01 … .b99 are all key files");
        // In the folder the temporary file is in, so that the backup is beside the file replaced.
        ::unlinkat(m_folder.get(), backup.filename().c_str(), 0);
        if (::linkat(m_folder.get(), m_target.path.filename().c_str(), m_folder.get(), backup.filename().c_str(), 0) != 0) {
            std::error_code error;
            fs::copy_file(m_target.path, backup, fs::copy_options::overwrite_existing, error);
            if (error) {
                errno = error.value();
                return abandon("cannot keep the old file as " + shown_beside(backup));
            }
        }
        kept = backup;
        return true;
    }

    std::string shown_beside(const fs::path& file) const { return (m_shown_folder / file.filename()).string(); }
    std::string shown_folder() const { return m_shown_folder.empty() ? std::string(".") : m_shown_folder.string(); }

    bool refuse(const std::string& message)
    {
        m_outcome = Diagnostic{m_shown, 0, message};
        return false;
    }

    // The problem with the system's reason; the temporary file goes.
    bool abandon(const std::string& what)
    {
        const int reason = errno;
        m_file.close();
        if (!m_temporary.empty())
            ::unlinkat(m_folder.get(), m_temporary.c_str(), 0);
        m_temporary.clear();
        m_unfinished.reset();
        return refuse(what + ": " + system_reason(reason));
    }

    ReplaceableTarget m_target;
    std::string m_shown;
    fs::path m_shown_folder;
    const KeyFileGuard* m_inputs;
    FileDescriptor m_old;
    std::uintmax_t m_same = 0; // bytes of the new content equal to the old file's first bytes
    std::uintmax_t m_size = 0; // bytes of the new content written after them (the file: both)
    bool m_differs;
    FileDescriptor m_file{-1};
    // The folder of the temporary file, open while m_unfinished may know it (declared before
    // it, so that the file is forgotten before the folder is closed).
    FileDescriptor m_folder{-1};
    std::string m_temporary; // its name in m_folder
    std::optional<UnfinishedFile> m_unfinished;
    Expected<void> m_outcome = ok; // the first problem, once there is one
};

} // namespace

namespace {

// `requested` replaced by write_content's chunks; messages name it `shown`, and name its folder
// `shown_folder` (empty: the folder of the file replaced, a link's target's).
Expected<WriteResult> replace_file(const fs::path& requested, const std::string& shown, const fs::path& shown_folder,
                                   const ContentWriter& write_content, const KeyFileGuard* inputs, Durability durability)
{
    const Expected<ReplaceableTarget> target = replaceable_target(requested, shown);
    if (!target)
        return target.error();
    Replacement replacement(*target, shown, shown_folder.empty() ? target->path.parent_path() : shown_folder, inputs);
    write_content([&replacement](std::string_view chunk) { return replacement.add(chunk); });
    return replacement.finish(durability);
}

} // namespace

Expected<WriteResult> write_file_atomically(const fs::path& requested, const ContentWriter& write_content,
                                            const KeyFileGuard* inputs, Durability durability)
{
    return replace_file(requested, requested.string(), {}, write_content, inputs, durability);
}

Expected<OutputFolder> OutputFolder::open(const fs::path& folder)
{
    const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (descriptor < 0)
        return Diagnostic{folder.string(), 0, "cannot open the folder to write into it: " + system_reason(errno)};
    const fs::path through = fs::path("/proc/self/fd") / std::to_string(descriptor);
    return OutputFolder(folder, descriptor, ::access(through.c_str(), X_OK) == 0);
}

OutputFolder::OutputFolder(OutputFolder&& other) noexcept
    : m_path(std::move(other.m_path))
    , m_descriptor(std::exchange(other.m_descriptor, -1))
    , m_reached_by_descriptor(other.m_reached_by_descriptor)
{
}

OutputFolder::~OutputFolder()
{
    if (m_descriptor >= 0)
        ::close(m_descriptor);
}

fs::path OutputFolder::reached(const std::string& name) const
{
    // The kernel resolves /proc/self/fd/N to the folder open as N, wherever it now is.
    if (!m_reached_by_descriptor)
        return m_path / name;
    return fs::path("/proc/self/fd") / std::to_string(m_descriptor) / name;
}

Expected<WriteResult> write_file_atomically(const OutputFolder& folder, const std::string& name,
                                            const ContentWriter& write_content, const KeyFileGuard* inputs,
                                            Durability durability)
{
    const fs::path shown_folder = folder.path().empty() ? fs::path(".") : folder.path();
    return replace_file(folder.reached(name), (folder.path() / name).string(), shown_folder, write_content, inputs,
                        durability);
}

Expected<WriteResult> write_file_atomically(const OutputFolder& folder, const std::string& name, std::string_view content,
                                            const KeyFileGuard* inputs, Durability durability)
{
    return write_file_atomically(
        folder, name, [content](const ContentSink& sink) { sink(content); }, inputs, durability);
}

Expected<WriteResult> write_file_atomically(const fs::path& requested, std::string_view content,
                                            const KeyFileGuard* inputs, Durability durability)
{
    return write_file_atomically(
        requested, [content](const ContentSink& sink) { sink(content); }, inputs, durability);
}

Expected<void> check_writable(const fs::path& requested, ReadOnlyTarget read_only)
{
    const std::string shown = requested.string();
    const Expected<ReplaceableTarget> target = replaceable_target(requested, shown);
    if (!target)
        return target.error();
    if (read_only == ReadOnlyTarget::refused && target->exists && is_read_only(target->path, target->status))
        return Diagnostic{shown, 0, "is read-only (mode " + octal_mode(target->status.st_mode) + "); not replaced"};
    const fs::path folder = target->path.has_parent_path() ? target->path.parent_path() : fs::path(".");
    struct stat folder_status {};
    if (::stat(folder.c_str(), &folder_status) != 0)
        return Diagnostic{shown, 0, "cannot be written: its folder " + folder.string() + ": " + system_reason(errno)};
    if (!S_ISDIR(folder_status.st_mode))
        return Diagnostic{shown, 0, "cannot be written: " + folder.string() + " is not a folder"};
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return Diagnostic{shown, 0, "cannot be written: its folder " + folder.string() + ": " + system_reason(errno)};
    return ok;
}

namespace {

// Whether the file at `path`, `size` bytes long, holds exactly what write_content makes; read in
// pieces beside the chunks, never whole.
bool file_holds(const fs::path& path, std::uintmax_t size, const ContentWriter& write_content)
{
    FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (file.get() < 0)
        return false;
    std::uintmax_t compared = 0;
    bool same = true;
    write_content([&](std::string_view chunk) {
        compared += chunk.size();
        if (compared > size)
            same = false;
        char buffer[1 << 16];
        while (same && !chunk.empty()) {
            const ssize_t got = ::read(file.get(), buffer, std::min(sizeof buffer, chunk.size()));
            if (got < 0 && errno == EINTR)
                continue;
            same = got > 0 && std::memcmp(buffer, chunk.data(), static_cast<std::size_t>(got)) == 0;
            chunk.remove_prefix(same ? static_cast<std::size_t>(got) : chunk.size());
        }
        return same;
    });
    return same && compared == size;
}

} // namespace

Expected<void> check_replaceable(const fs::path& requested, const ContentWriter& write_content,
                                 const KeyFileGuard* inputs)
{
    if (Expected<void> writable = check_writable(requested, ReadOnlyTarget::left_to_the_write); !writable)
        return writable;
    const std::string shown = requested.string();
    const Expected<ReplaceableTarget> target = replaceable_target(requested, shown);
    if (!target || !target->exists)
        return ok;
    const fs::path backup = backup_path_for(target->path, inputs);
    Expected<void> problem = ok;
    if (is_read_only(target->path, target->status))
        problem = Diagnostic{shown, 0, "is read-only (mode " + octal_mode(target->status.st_mode) + "); not replaced"};
    else if (backup.empty())
        problem = Diagnostic{shown, 0, "cannot keep the old file: its .bak and .b01 … .b99 are all key files"};
    else
        problem = check_backup_replaceable(backup, shown, backup.string());
    // Only a file whose content changes is replaced, and only then do these matter.
    if (problem || file_holds(target->path, static_cast<std::uintmax_t>(target->status.st_size), write_content))
        return ok;
    return problem;
}

Expected<void> flush_file_system(const fs::path& folder)
{
    FileDescriptor opened(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (opened.get() < 0 || ::syncfs(opened.get()) != 0)
        return Diagnostic{folder.string(), 0, "cannot flush the files written to disk: " + system_reason(errno)};
    return ok;
}

} // namespace apcs
