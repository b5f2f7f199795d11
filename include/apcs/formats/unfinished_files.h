#pragma once

#include <functional>
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

// A folder of the program's own, made by create_unfinished_folder (apcs grade's private folder of
// copies and replays), which remove_unfinished_files() removes with everything in it while it is
// known: by its parent's descriptor (which must stay open meanwhile) and its name. One is known at
// a time; a second is made but not known. The owner removes it when done, then lets it be forgotten.
class UnfinishedFolder {
public:
    UnfinishedFolder(int parent, const std::string& name) noexcept;
    ~UnfinishedFolder();
    UnfinishedFolder(const UnfinishedFolder&) = delete;
    UnfinishedFolder& operator=(const UnfinishedFolder&) = delete;

private:
    bool m_known = false;
};

// As mkdtemp(pattern) in the folder open as `parent` (pattern a name ending in XXXXXX, which is
// replaced; mode 0700), the folder made known in `known` before any signal can end the program:
// 0, or -1 with errno (EINTR once remove_unfinished_files has begun).
int create_unfinished_folder(int parent, std::string& pattern, std::optional<UnfinishedFolder>& known) noexcept;

// `make` run unless a stop has begun, with this thread's signals blocked meanwhile: what it makes
// (a folder inside the unfinished folder, a log line's file) is made before a stop's removal
// begins, and removed by it, or not at all, while other threads go on until the program ends.
// False, errno EINTR and `make` not run once a stop has begun. `make` must be short: a stop waits.
bool make_unless_stopping(const std::function<void()>& make);

// Removes every temporary file being written now and the unfinished folder with all it holds,
// first waiting for any being made on another thread, and makes no more from then on (the
// threads writing run until the program ends: one made after the removal would stay).
// Async-signal-safe: for a signal handler that then ends the program.
void remove_unfinished_files() noexcept;

} // namespace apcs
