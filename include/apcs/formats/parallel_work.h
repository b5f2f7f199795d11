#pragma once

#include <cstddef>
#include <functional>

namespace apcs {

// Calls work(index) for every index 0 … count−1, shared among up to `workers` threads (this one
// included). An exception thrown by a call (std::bad_alloc, say) stops further indices from
// starting and is rethrown here once every thread has ended: an exception may not leave a thread,
// where it would end the program at once, with the terminal left raw and no message.
void for_each_index_in_parallel(std::size_t count, std::size_t workers, const std::function<void(std::size_t)>& work);

} // namespace apcs
