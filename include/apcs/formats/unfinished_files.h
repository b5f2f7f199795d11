#pragma once

#include <string>

namespace apcs {

// A temporary file being written (write_file_atomically's), known for its lifetime to
// remove_unfinished_files(), so that a program ended by a signal leaves none behind. Up to 64 are
// known at once (the writers run on at most 8 threads); more are written but not known.
class UnfinishedFile {
public:
    explicit UnfinishedFile(const std::string& path) noexcept;
    ~UnfinishedFile();
    UnfinishedFile(const UnfinishedFile&) = delete;
    UnfinishedFile& operator=(const UnfinishedFile&) = delete;

private:
    int m_slot = -1;
};

// Removes every temporary file being written now. Async-signal-safe: for a signal handler that
// then ends the program.
void remove_unfinished_files() noexcept;

} // namespace apcs
