#pragma once

// What a folder holds, entry by entry, as lstat() and the bytes show it: taken before and after a
// session so that the folder fuzzer can say what the session changed.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <sys/stat.h>

namespace apcs::fuzzing {

// A file's identity: one file has it under every hard link and every symbolic link to it.
struct FileIdentity {
    dev_t device = 0;
    ino_t inode = 0;
    bool operator==(const FileIdentity&) const = default;
};

struct EntryState {
    mode_t mode = 0; // type and permissions, from lstat()
    FileIdentity own;
    // Where a symbolic link points, as written in it.
    std::string link_target;
    // The file the entry names, links followed; none for a dangling link.
    bool reaches_file = false;
    FileIdentity reached;
    // The bytes of a regular file, or of the regular file a link reaches. A FIFO is never opened.
    std::string bytes;
    bool operator==(const EntryState&) const = default;
};

// Relative path in the folder → its state; directories are walked, links to them are not.
using FolderState = std::map<std::string, EntryState>;

inline std::string bytes_of(const std::filesystem::path& file)
{
    std::ifstream stream(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

inline EntryState state_of(const std::filesystem::path& entry)
{
    EntryState state;
    struct stat status {};
    if (::lstat(entry.c_str(), &status) != 0)
        return state;
    state.mode = status.st_mode;
    state.own = {status.st_dev, status.st_ino};
    if (S_ISLNK(status.st_mode)) {
        std::error_code error;
        state.link_target = std::filesystem::read_symlink(entry, error).string();
    }
    if (::stat(entry.c_str(), &status) == 0) {
        state.reaches_file = true;
        state.reached = {status.st_dev, status.st_ino};
        if (S_ISREG(status.st_mode))
            state.bytes = bytes_of(entry);
    }
    return state;
}

inline FolderState snapshot(const std::filesystem::path& folder)
{
    FolderState state;
    std::error_code error;
    for (std::filesystem::recursive_directory_iterator entry(folder, error), end; !error && entry != end;
         entry.increment(error))
        state[entry->path().lexically_relative(folder).string()] = state_of(entry->path());
    return state;
}

// Whether `name` looks like the temporary file of an atomic write: .NAME.XXXXXX (mkstemp).
inline bool is_temporary_name(const std::string& name)
{
    return name.size() >= 9 && name.front() == '.' && name[name.size() - 7] == '.';
}

} // namespace apcs::fuzzing
