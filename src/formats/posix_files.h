#pragma once

// POSIX file helpers shared by the reading (file_io.cpp) and the atomic writing
// (atomic_write.cpp) of files; not part of the library's interface.

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>

namespace apcs::posix_files {

inline std::string system_reason(int error_number) { return std::strerror(error_number); }

// Closes a POSIX file descriptor when it goes out of scope.
class FileDescriptor {
public:
    explicit FileDescriptor(int descriptor) : m_descriptor(descriptor) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() { close(); }
    int get() const { return m_descriptor; }
    void reset(int descriptor)
    {
        close();
        m_descriptor = descriptor;
    }
    int close()
    {
        const int result = m_descriptor >= 0 ? ::close(m_descriptor) : 0;
        m_descriptor = -1;
        return result;
    }

private:
    int m_descriptor;
};

inline bool write_all(int descriptor, std::string_view content)
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

// What a file that is not a regular file is, in a message: "a FIFO", "a character device"...
inline std::string kind_of(mode_t mode)
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

inline std::string not_regular(mode_t mode) { return "is not a regular file (" + kind_of(mode) + ")"; }

inline std::string octal_mode(mode_t mode)
{
    char text[8];
    std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
    return text;
}

// Whether the user means the file to stay as it is: no write permission for them. As root,
// access() and faccessat() say yes to every file, so there the mode bits decide: a file that
// nobody may write (0444) is one its owner protected on purpose, and root replacing it would
// quietly undo that. Other users ask the kernel, which also knows ACLs and groups.
inline bool is_read_only(const std::filesystem::path& file, const struct stat& status)
{
    if (::geteuid() == 0)
        return (status.st_mode & 0222) == 0;
    return ::faccessat(AT_FDCWD, file.c_str(), W_OK, AT_EACCESS) != 0 && errno == EACCES;
}


} // namespace apcs::posix_files
