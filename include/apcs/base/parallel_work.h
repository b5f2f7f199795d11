#pragma once

#include <cstddef>
#include <functional>

// Work shared among threads, in the two shapes the layers above need. Both keep what a thread
// throws (std::bad_alloc, say) and rethrow it on the calling thread once every thread has ended:
// an exception may not leave a thread, where it would end the program at once, with the terminal
// left raw and no message. Where two threads throw, the lower-numbered one's exception is rethrown
// (this thread is number 0). When no thread can be started (out of threads or address space), the
// work is done on fewer threads, down to this one alone.
namespace apcs {

// Calls work(first, end) for the indices 0 … count − 1: in two halves on two threads (this one
// included) when count is at least twice `worth_a_thread` and the machine has two cores, else once
// for all. The halves are [0, count / 2) and [count / 2, count); when the second thread cannot be
// started, this one does both, one after the other.
void split_across_cores(std::size_t count, std::size_t worth_a_thread,
                        const std::function<void(std::size_t first, std::size_t end)>& work);

// Calls work(index) for every index 0 … count − 1, shared among up to `workers` threads (this one
// included), each taking the next index not yet taken. An exception thrown by a call stops further
// indices from starting.
void for_each_index_in_parallel(std::size_t count, std::size_t workers, const std::function<void(std::size_t)>& work);

} // namespace apcs
