#include "apcs/formats/unfinished_files.h"

#include <array>
#include <atomic>
#include <climits>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <pthread.h>
#include <string_view>
#include <sys/random.h>
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

// mkstemp in the folder open as `folder`: its XXXXXX replaced by random letters and digits until
// a name is free (O_EXCL), at most 100 tries.
int make_temporary_at(int folder, std::string& pattern) noexcept
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
        const int descriptor = ::openat(folder, pattern.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (descriptor >= 0 || errno != EEXIST)
            return descriptor;
    }
    return -1;
}

} // namespace

int create_unfinished_file(int folder, std::string& pattern, std::optional<UnfinishedFile>& known) noexcept
{
    // With every signal blocked here, a stop's handler runs on another thread (or after this),
    // which then waits for being_made to fall to 0: it cannot wait on its own thread.
    sigset_t all;
    sigset_t previous;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &previous);
    being_made.fetch_add(1);
    int descriptor = -1;
    if (stopping.load()) {
        errno = EINTR;
    } else {
        descriptor = make_temporary_at(folder, pattern);
        if (descriptor >= 0)
            known.emplace(folder, pattern);
    }
    being_made.fetch_sub(1);
    const int reason = errno;
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    errno = reason;
    return descriptor;
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
}

} // namespace apcs
