#include "apcs/formats/file_io.h"

#include "apcs/animation/memory_budget.h"
#include "apcs/formats/text_fields.h"
#include "apcs/formats/unfinished_files.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace apcs {

namespace fs = std::filesystem;

namespace {

std::string system_reason(int error_number) { return std::strerror(error_number); }

Diagnostic too_large(const std::string& shown, std::uintmax_t bytes, std::uintmax_t most_bytes)
{
    return Diagnostic{shown, 0, "is " + std::to_string(bytes) + " bytes; expected at most " + std::to_string(most_bytes) +
                                    " bytes (" + memory::byte_count_text(most_bytes) + ")"};
}

// No text APCS reads holds a NUL byte: a binary file is refused at the first one, before the rest
// of it is read. `read` is the text before `chunk`, for the line number.
std::optional<Diagnostic> refuse_nul_byte(const std::string& shown, std::string_view read, std::string_view chunk)
{
    const std::size_t nul = chunk.find('\0');
    if (nul == std::string_view::npos)
        return std::nullopt;
    const auto lines = std::count(read.begin(), read.end(), '\n') + std::count(chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
    return Diagnostic{shown, 1 + static_cast<int>(lines), "NUL byte; expected a text file"};
}

// Closes a POSIX file descriptor when it goes out of scope.
class FileDescriptor {
public:
    explicit FileDescriptor(int descriptor) : m_descriptor(descriptor) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() { close(); }
    int get() const { return m_descriptor; }
    int close()
    {
        const int result = m_descriptor >= 0 ? ::close(m_descriptor) : 0;
        m_descriptor = -1;
        return result;
    }

private:
    int m_descriptor;
};

bool write_all(int descriptor, std::string_view content)
{
    while (!content.empty()) {
        const ssize_t written = ::write(descriptor, content.data(), content.size());
        if (written < 0) {
            if (errno == EINTR)
                continue;
            return false;
        }
        content.remove_prefix(static_cast<std::size_t>(written));
    }
    return true;
}

// Whether the file, of `size` bytes, holds exactly `content`, compared chunk by chunk so that no
// copy of a large file is held in memory.
bool holds_exactly(const fs::path& file, off_t size, std::string_view content)
{
    if (size < 0 || static_cast<std::size_t>(size) != content.size())
        return false;
    FileDescriptor input(::open(file.c_str(), O_RDONLY | O_CLOEXEC));
    if (input.get() < 0)
        return false;
    char buffer[1 << 16];
    std::size_t compared = 0;
    while (compared < content.size()) {
        const ssize_t got = ::read(input.get(), buffer, sizeof buffer);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0 || static_cast<std::size_t>(got) > content.size() - compared ||
            content.compare(compared, static_cast<std::size_t>(got), buffer, static_cast<std::size_t>(got)) != 0)
            return false;
        compared += static_cast<std::size_t>(got);
    }
    return true;
}

// What a file that is not a regular file is, in a message: "a FIFO", "a character device"...
std::string kind_of(mode_t mode)
{
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISSOCK(mode))
        return "a socket";
    if (S_ISLNK(mode))
        return "a symbolic link";
    return "not a regular file";
}

std::string not_regular(mode_t mode) { return "is not a regular file (" + kind_of(mode) + ")"; }

std::string octal_mode(mode_t mode)
{
    char text[8];
    std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
    return text;
}

// Whether the user means the file to stay as it is: no write permission for them. As root,
// access() and faccessat() say yes to every file, so there the mode bits decide: a file that
// nobody may write (0444) is one its owner protected on purpose, and root replacing it would
// quietly undo that. Other users ask the kernel, which also knows ACLs and groups.
bool is_read_only(const fs::path& file, const struct stat& status)
{
    if (::geteuid() == 0)
        return (status.st_mode & 0222) == 0;
    return ::faccessat(AT_FDCWD, file.c_str(), W_OK, AT_EACCESS) != 0 && errno == EACCES;
}

// NAME.bak is replaced by the old file only when it is a writable regular file or absent: a FIFO, a
// link, a directory or a read-only file there is the user's, and is left as it is.
std::optional<Diagnostic> backup_refusal(const fs::path& backup, const std::string& shown)
{
    struct stat status {};
    if (backup.empty() || ::lstat(backup.c_str(), &status) != 0)
        return std::nullopt;
    const std::string cannot = "cannot keep the old file as " + backup.string() + ": it ";
    if (S_ISLNK(status.st_mode))
        return Diagnostic{shown, 0, cannot + "is a symbolic link; a backup replaces only a regular file"};
    if (S_ISDIR(status.st_mode))
        return Diagnostic{shown, 0, cannot + "is a directory; a backup replaces only a regular file"};
    if (!S_ISREG(status.st_mode))
        return Diagnostic{shown, 0, cannot + not_regular(status.st_mode) + "; a backup replaces only a regular file"};
    if (is_read_only(backup, status))
        return Diagnostic{shown, 0, cannot + "is read-only (mode " + octal_mode(status.st_mode) + "); not replaced"};
    return std::nullopt;
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

Expected<std::string> read_text_file(const fs::path& name, std::uintmax_t most_bytes)
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
    std::string content;
    char buffer[1 << 16];
    while (true) {
        const ssize_t got = ::read(file.get(), buffer, sizeof buffer);
        if (got < 0) {
            if (errno == EINTR)
                continue;
            return Diagnostic{shown, 0, "cannot read: " + system_reason(errno)};
        }
        if (got == 0)
            break;
        const std::string_view chunk(buffer, static_cast<std::size_t>(got));
        if (auto binary = refuse_nul_byte(shown, content, chunk))
            return *std::move(binary);
        // A file that grew while it was read.
        if (content.size() + chunk.size() > most_bytes)
            return too_large(shown, content.size() + chunk.size(), most_bytes);
        if (content.empty())
            content.reserve(static_cast<std::size_t>(status.st_size));
        content.append(chunk);
    }
    return content;
}

Expected<DatFile> read_dat_file(const fs::path& name, std::size_t minimum_points)
{
    // "-" is standard input, read like a keystroke script: a pipe, once, to its end.
    if (name == "-") {
        Expected<std::string> piped = read_script_text(name);
        if (!piped)
            return piped.error();
        return parse_dat(*piped, "standard input", minimum_points);
    }
    Expected<std::string> text = read_text_file(name);
    if (!text)
        return text.error();
    return parse_dat(*text, name.string(), minimum_points);
}

Expected<Graphic> read_key_frame(const fs::path& name)
{
    const Expected<DatFile> file = read_dat_file(name);
    if (!file)
        return file.error();
    return graphic_from(*file);
}

namespace {

// Everything a pipe holds until its writer closes it, at most `most_bytes`.
Expected<std::string> read_pipe_to_end(int descriptor, const std::string& shown, std::uintmax_t most_bytes)
{
    std::string content;
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
        if (auto binary = refuse_nul_byte(shown, content, chunk))
            return *std::move(binary);
        if (content.size() + chunk.size() > most_bytes)
            return too_large(shown, content.size() + chunk.size(), most_bytes);
        content.append(chunk);
    }
}

} // namespace

Expected<std::string> read_script_text(const fs::path& name, std::uintmax_t most_bytes)
{
    if (name == "-")
        return read_pipe_to_end(STDIN_FILENO, "standard input", most_bytes);
    struct stat status {};
    if (::stat(name.c_str(), &status) != 0 || !S_ISFIFO(status.st_mode))
        return read_text_file(name, most_bytes);
    FileDescriptor pipe(::open(name.c_str(), O_RDONLY | O_CLOEXEC));
    if (pipe.get() < 0)
        return Diagnostic{name.string(), 0, "cannot open: " + system_reason(errno)};
    return read_pipe_to_end(pipe.get(), name.string(), most_bytes);
}

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

Expected<WriteResult> write_file_atomically(const fs::path& requested, std::string_view content,
                                            const KeyFileGuard* inputs, Durability durability)
{
    const std::string shown = requested.string();
    // Only regular files are ever replaced. A symbolic link is written through to the file it
    // names (replaced in its own folder; the link stays) when that is a regular file; a device, a
    // FIFO, a socket or a directory, named or linked to, is refused and left as it is.
    fs::path target = requested;
    struct stat status {};
    bool exists = false;
    if (::lstat(requested.c_str(), &status) == 0) {
        if (S_ISLNK(status.st_mode)) {
            std::error_code error;
            const fs::path named = fs::read_symlink(requested, error);
            const std::string link_to = "is a symbolic link to " + (error ? std::string("a file") : named.string());
            if (::stat(requested.c_str(), &status) != 0)
                return Diagnostic{shown, 0, link_to + ", which does not exist (" + system_reason(errno) + "); APCS writes only regular files"};
            if (!S_ISREG(status.st_mode))
                return Diagnostic{shown, 0, link_to + ", which " + not_regular(status.st_mode) + "; APCS writes only regular files"};
            target = fs::canonical(requested, error);
            if (error)
                return Diagnostic{shown, 0, link_to + ", which cannot be followed: " + error.message()};
        } else if (S_ISDIR(status.st_mode)) {
            return Diagnostic{shown, 0, "is a directory; cannot write a file there"};
        } else if (!S_ISREG(status.st_mode)) {
            return Diagnostic{shown, 0, not_regular(status.st_mode) + "; APCS writes only regular files"};
        }
        exists = true;
    }
    if (exists && holds_exactly(target, status.st_size, content))
        return WriteResult{WriteOutcome::unchanged, {}};
    if (exists && is_read_only(target, status))
        return Diagnostic{shown, 0, "is read-only (mode " + octal_mode(status.st_mode) + "); not replaced"};
    if (exists)
        if (auto problem = backup_refusal(backup_path_for(target, inputs), shown))
            return *problem;
    // A new file is 0644; a replaced one keeps its mode, and its owner and group where allowed.
    const mode_t mode = exists ? (status.st_mode & 07777) : 0644;
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::string temporary = (folder / temporary_name_for(folder, target.filename().string())).string();
    FileDescriptor file(::mkstemp(temporary.data()));
    if (file.get() < 0)
        return Diagnostic{shown, 0, "cannot create a temporary file in " + folder.string() + ": " + system_reason(errno)};
    // Known until this function returns, renamed or removed: a signal meanwhile removes it.
    const UnfinishedFile unfinished(temporary);
    const auto abandon = [&](const std::string& what) {
        const int reason = errno;
        file.close();
        ::unlink(temporary.c_str());
        return Diagnostic{shown, 0, what + ": " + system_reason(reason)};
    };
    if (!write_all(file.get(), content))
        return abandon("cannot write");
    if (durability == Durability::each_file && ::fsync(file.get()) != 0)
        return abandon("cannot flush to disk");
    if (exists && (status.st_uid != ::geteuid() || status.st_gid != ::getegid())) {
        // Allowed to root, and to the owner for a group of theirs; otherwise the file becomes the
        // user's, as any new file would.
        [[maybe_unused]] const int ignored = ::fchown(file.get(), status.st_uid, status.st_gid);
    }
    if (::fchmod(file.get(), mode) != 0)
        return abandon("cannot set permissions");
    if (file.close() != 0)
        return abandon("cannot close");

    WriteResult result{exists ? WriteOutcome::replaced : WriteOutcome::created, {}};
    if (exists) {
        // A hard link keeps the old content as .bak while the target itself stays in place until
        // the rename replaces it, so no moment exists without the user's file.
        const fs::path backup = backup_path_for(target, inputs);
        if (backup.empty()) {
            file.close();
            ::unlink(temporary.c_str());
            return Diagnostic{shown, 0, "cannot keep the old file: its .bak and .b01 … .b99 are all key files"};
        }
        ::unlink(backup.c_str());
        std::error_code error;
        if (::link(target.c_str(), backup.c_str()) != 0) {
            fs::copy_file(target, backup, fs::copy_options::overwrite_existing, error);
            if (error) {
                errno = error.value();
                return abandon("cannot keep the old file as " + backup.string());
            }
        }
        result.backup = backup;
    }
    if (::rename(temporary.c_str(), target.c_str()) != 0)
        return abandon("cannot replace the file");
    return result;
}

std::optional<Diagnostic> flush_file_system(const fs::path& folder)
{
    FileDescriptor opened(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (opened.get() < 0 || ::syncfs(opened.get()) != 0)
        return Diagnostic{folder.string(), 0, "cannot flush the files written to disk: " + system_reason(errno)};
    return std::nullopt;
}

} // namespace apcs
