#include "apcs/formats/unfinished_files.h"

#include <array>
#include <atomic>
#include <climits>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <pthread.h>
#include <unistd.h>

namespace apcs {

namespace {

constexpr int slot_count = 64;

// A signal handler may read these at any moment: a slot's path is complete before it is marked
// in use, and is not touched again until it is released.
struct Slot {
    std::atomic<bool> claimed{false};
    std::atomic<bool> in_use{false};
    char path[PATH_MAX] = {};
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

UnfinishedFile::UnfinishedFile(const std::string& path) noexcept
{
    if (path.size() >= PATH_MAX)
        return;
    for (int index = 0; index < slot_count; ++index) {
        Slot& slot = slots()[static_cast<std::size_t>(index)];
        bool expected = false;
        if (!slot.claimed.compare_exchange_strong(expected, true))
            continue;
        std::memcpy(slot.path, path.c_str(), path.size() + 1);
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

int create_unfinished_file(std::string& pattern, std::optional<UnfinishedFile>& known) noexcept
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
        descriptor = ::mkstemp(pattern.data());
        if (descriptor >= 0)
            known.emplace(pattern);
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
            ::unlink(slot.path);
}

} // namespace apcs
