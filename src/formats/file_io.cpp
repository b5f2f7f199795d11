#include "apcs/formats/file_io.h"

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

namespace apcs {

namespace fs = std::filesystem;

namespace {

// Larger inputs than this cannot be valid: 10^6 points of at most 4096 bytes would be 4 GB, but
// no real key file comes near; refusing here keeps memory bounded for any input.
constexpr std::uintmax_t max_input_bytes = 1ull << 30;

std::string system_reason(int error_number) { return std::strerror(error_number); }

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

// Whether the file's bytes are `content`, compared chunk by chunk so that no copy of a large file
// is held in memory.
bool holds_exactly(const fs::path& file, std::string_view content)
{
    std::error_code error;
    if (fs::file_size(file, error) != content.size() || error)
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

} // namespace

fs::path resolve_input_path(const fs::path& name)
{
    std::error_code error;
    if (fs::exists(name, error))
        return name;
    const fs::path folder = name.has_parent_path() ? name.parent_path() : fs::path(".");
    const std::string wanted = name.filename().string();
    for (fs::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error))
        if (equals_ignoring_case(entry->path().filename().string(), wanted))
            return name.has_parent_path() ? folder / entry->path().filename() : entry->path().filename();
    return name;
}

Expected<std::string> read_text_file(const fs::path& name)
{
    const std::string shown = name.string();
    const fs::path path = resolve_input_path(name);
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
        if (content.size() + static_cast<std::size_t>(got) > max_input_bytes)
            return Diagnostic{shown, 0, "is larger than 1 GiB; expected a .dat file"};
        content.append(buffer, static_cast<std::size_t>(got));
    }
    return content;
}

Expected<DatFile> read_dat_file(const fs::path& name, std::size_t minimum_points)
{
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
                                            const KeyFileGuard* inputs)
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
    if (exists && holds_exactly(target, content))
        return WriteResult{WriteOutcome::unchanged, {}};
    if (exists && is_read_only(target, status))
        return Diagnostic{shown, 0, "is read-only (mode " + octal_mode(status.st_mode) + "); not replaced"};
    // A new file is 0644; a replaced one keeps its mode, and its owner and group where allowed.
    const mode_t mode = exists ? (status.st_mode & 07777) : 0644;
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::string temporary = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
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
    if (::fsync(file.get()) != 0)
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

} // namespace apcs
