#pragma once

#include <optional>
#include <string>

namespace apcs {

// A temporary file being written (write_file_atomically's), known for its lifetime to
// remove_unfinished_files(), so that a program ended by a signal leaves none behind. It is known
// by its folder's descriptor and its name in that folder, not by a path: a folder renamed or moved
// meanwhile still has it removed. Up to 64 are known at once (the writers run on at most 8
// threads); more are written but not known. The folder's descriptor must stay open while it is
// known.
class UnfinishedFile {
public:
    UnfinishedFile(int folder, const std::string& name) noexcept;
    ~UnfinishedFile();
    UnfinishedFile(const UnfinishedFile&) = delete;
    UnfinishedFile& operator=(const UnfinishedFile&) = delete;

private:
    int m_slot = -1;
};

// As mkstemp(pattern) in the folder open as `folder` (pattern a name ending in XXXXXX, which is
// replaced), the file made known in `known` before any signal can end the program: the
// descriptor, or -1 with errno (EINTR once remove_unfinished_files has begun, so that no file is
// made while the program is being stopped). Signals wait while the file is made.
int create_unfinished_file(int folder, std::string& pattern, std::optional<UnfinishedFile>& known) noexcept;

// Removes every temporary file being written now, first waiting for any being made on another
// thread, and makes no more from then on (the threads writing run until the program ends: one
// made after the removal would stay). Async-signal-safe: for a signal handler that then ends the
// program.
void remove_unfinished_files() noexcept;

} // namespace apcs
