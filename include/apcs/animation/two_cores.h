#pragma once

#include <cstddef>
#include <functional>

namespace apcs {

// Calls work(first, end) for the indices 0 … count − 1: in two halves on two threads (this one
// included) when count is at least twice `worth_a_thread` and the machine has two cores, else once
// for all (also when no thread can be started). An exception from either half (std::bad_alloc, say) is rethrown here once both have
// ended: an exception may not leave a thread, where it would end the program at once, with the
// terminal left raw and no message.
void split_across_cores(std::size_t count, std::size_t worth_a_thread,
                        const std::function<void(std::size_t first, std::size_t end)>& work);

} // namespace apcs
