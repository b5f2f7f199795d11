#include "apcs/formats/unfinished_files.h"

#include <functional>

#include <array>
#include <atomic>
#include <climits>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <string_view>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

namespace apcs {

namespace {

constexpr int slot_count = 64;

// A signal handler may read these at any moment: a slot's path is complete before it is marked
// in use, and is not touched again until it is released.
struct Slot {
    std::atomic<bool> claimed{false};
    std::atomic<bool> in_use{false};
    int folder = -1;
    char name[NAME_MAX + 1] = {};
};

std::array<Slot, slot_count>& slots()
{
    static std::array<Slot, slot_count> all;
    return all;
}

// Set when a stop begins: no temporary file is made after it.
std::atomic<bool> stopping{false};
// Temporary files being made right now (between mkstemp and their slot), which a stop waits for.
std::atomic<int> being_made{0};

} // namespace

UnfinishedFile::UnfinishedFile(int folder, const std::string& name) noexcept
{
    if (name.size() > NAME_MAX)
        return;
    for (int index = 0; index < slot_count; ++index) {
        Slot& slot = slots()[static_cast<std::size_t>(index)];
        bool expected = false;
        if (!slot.claimed.compare_exchange_strong(expected, true))
            continue;
        slot.folder = folder;
        std::memcpy(slot.name, name.c_str(), name.size() + 1);
        slot.in_use.store(true, std::memory_order_release);
        m_slot = index;
        return;
    }
}

UnfinishedFile::~UnfinishedFile()
{
    if (m_slot < 0)
        return;
    Slot& slot = slots()[static_cast<std::size_t>(m_slot)];
    slot.in_use.store(false, std::memory_order_release);
    slot.claimed.store(false, std::memory_order_release);
}

namespace {

// The folder a stop removes, if one is known.
struct FolderSlot {
    std::atomic<bool> claimed{false};
    std::atomic<bool> in_use{false};
    int parent = -1;
    char name[NAME_MAX + 1] = {};
};

FolderSlot& folder_slot()
{
    static FolderSlot slot;
    return slot;
}

} // namespace

UnfinishedFolder::UnfinishedFolder(int parent, const std::string& name) noexcept
{
    FolderSlot& slot = folder_slot();
    bool free = false;
    if (name.size() > NAME_MAX || !slot.claimed.compare_exchange_strong(free, true))
        return;
    slot.parent = parent;
    std::memcpy(slot.name, name.c_str(), name.size() + 1);
    slot.in_use.store(true, std::memory_order_release);
    m_known = true;
}

UnfinishedFolder::~UnfinishedFolder()
{
    if (!m_known)
        return;
    folder_slot().in_use.store(false, std::memory_order_release);
    folder_slot().claimed.store(false, std::memory_order_release);
}

namespace {

// Makes the entry `name` in the folder open as `folder`: a descriptor or 0, or -1 with errno.
using MakeEntry = int (*)(int folder, const char* name) noexcept;

int make_file(int folder, const char* name) noexcept
{
    return ::openat(folder, name, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
}

int make_folder(int folder, const char* name) noexcept { return ::mkdirat(folder, name, 0700); }

// mkstemp in the folder open as `folder`: its XXXXXX replaced by random letters and digits until
// a name is free (O_EXCL, or mkdir's own EEXIST), at most 100 tries.
int make_unique_at(int folder, std::string& pattern, MakeEntry make) noexcept
{
    constexpr std::string_view letters = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    constexpr std::size_t unique = 6;
    if (pattern.size() < unique || pattern.compare(pattern.size() - unique, unique, "XXXXXX") != 0) {
        errno = EINVAL;
        return -1;
    }
    for (int attempt = 0; attempt < 100; ++attempt) {
        unsigned char random[unique] = {};
        if (::getrandom(random, sizeof random, 0) != static_cast<ssize_t>(sizeof random))
            return -1;
        for (std::size_t i = 0; i < unique; ++i)
            pattern[pattern.size() - unique + i] = letters[static_cast<std::size_t>(random[i]) % letters.size()];
        const int made = make(folder, pattern.c_str());
        if (made >= 0 || errno != EEXIST)
            return made;
    }
    return -1;
}

// `make` of a unique `pattern` in `folder`, `remember` called on the name made. With every signal
// blocked here, a stop's handler runs on another thread (or after this), which then waits for
// being_made to fall to 0 (it cannot wait on its own thread), and finds the entry known.
template <typename Remember>
int create_known(int folder, std::string& pattern, MakeEntry make, Remember remember) noexcept
{
    sigset_t all;
    sigset_t previous;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &previous);
    being_made.fetch_add(1);
    int made = -1;
    if (stopping.load()) {
        errno = EINTR;
    } else {
        made = make_unique_at(folder, pattern, make);
        if (made >= 0)
            remember();
    }
    being_made.fetch_sub(1);
    const int reason = errno;
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    errno = reason;
    return made;
}

// Everything in the folder `name` of the folder open as `parent`, then the folder, removed with
// system calls only (async-signal-safe: no allocation, no stdio); `depth` folders deep at most.
// Entries are removed while the folder is read, so it is read again until a pass removes nothing
// (an entry that cannot be removed stays: a stop must end), a few passes at most.
void remove_tree_at(int parent, const char* name, int depth) noexcept
{
    const int folder = ::openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (folder < 0)
        return;
    alignas(struct dirent64) char entries[2048];
    constexpr int most_passes = 8;
    bool removed = true;
    for (int pass = 0; removed && pass < most_passes; ++pass) {
        removed = false;
        ::lseek(folder, 0, SEEK_SET);
        for (ssize_t size; (size = ::getdents64(folder, entries, sizeof entries)) > 0;) {
            for (ssize_t at = 0; at < size;) {
                const auto* entry = reinterpret_cast<const struct dirent64*>(entries + at);
                at += entry->d_reclen;
                const std::string_view entry_name = entry->d_name;
                if (entry_name == "." || entry_name == "..")
                    continue;
                if (::unlinkat(folder, entry->d_name, 0) == 0) {
                    removed = true;
                } else if (errno == EISDIR && depth > 0) {
                    remove_tree_at(folder, entry->d_name, depth - 1);
                    removed = ::unlinkat(folder, entry->d_name, AT_REMOVEDIR) == 0 || removed;
                }
            }
        }
    }
    ::close(folder);
    ::unlinkat(parent, name, AT_REMOVEDIR);
}

} // namespace

int create_unfinished_folder(int parent, std::string& pattern, std::optional<UnfinishedFolder>& known) noexcept
{
    const int made = create_known(parent, pattern, make_folder, [&] { known.emplace(parent, pattern); });
    return made < 0 ? -1 : 0;
}

bool make_unless_stopping(const std::function<void()>& make)
{
    // As create_known: with every signal blocked here, a stop's handler runs on another thread
    // and waits for `make` to end before it removes anything.
    struct Blocked {
        sigset_t previous;
        Blocked()
        {
            sigset_t all;
            sigfillset(&all);
            pthread_sigmask(SIG_BLOCK, &all, &previous);
            being_made.fetch_add(1);
        }
        ~Blocked()
        {
            being_made.fetch_sub(1);
            const int reason = errno;
            pthread_sigmask(SIG_SETMASK, &previous, nullptr);
            errno = reason;
        }
        Blocked(const Blocked&) = delete;
        Blocked& operator=(const Blocked&) = delete;
    } blocked;
    if (stopping.load()) {
        errno = EINTR;
        return false;
    }
    make();
    return true;
}

int create_unfinished_file(int folder, std::string& pattern, std::optional<UnfinishedFile>& known) noexcept
{
    return create_known(folder, pattern, make_file, [&] { known.emplace(folder, pattern); });
}

void remove_unfinished_files() noexcept
{
    stopping.store(true);
    // A file being made is in its slot within one mkstemp: a short wait, spun (sleeping and
    // yielding are not async-signal-safe in every libc).
    while (being_made.load() > 0) {
    }
    for (Slot& slot : slots())
        if (slot.in_use.load(std::memory_order_acquire))
            ::unlinkat(slot.folder, slot.name, 0);
    // apcs grade's folder holds its copies and a work folder with what a session writes.
    constexpr int deepest = 8;
    if (FolderSlot& folder = folder_slot(); folder.in_use.load(std::memory_order_acquire))
        remove_tree_at(folder.parent, folder.name, deepest);
}

} // namespace apcs
