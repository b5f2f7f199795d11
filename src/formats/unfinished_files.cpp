#include "apcs/formats/unfinished_files.h"

#include <array>
#include <atomic>
#include <climits>
#include <cstring>
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

void remove_unfinished_files() noexcept
{
    for (Slot& slot : slots())
        if (slot.in_use.load(std::memory_order_acquire))
            ::unlink(slot.path);
}

} // namespace apcs
