#include "apcs/animation/two_cores.h"

#include <exception>
#include <system_error>
#include <thread>

namespace apcs {

void split_across_cores(std::size_t count, std::size_t worth_a_thread,
                        const std::function<void(std::size_t first, std::size_t end)>& work)
{
    if (count < 2 * worth_a_thread || std::thread::hardware_concurrency() < 2) {
        work(0, count);
        return;
    }
    const std::size_t middle = count / 2;
    std::exception_ptr second_problem;
    std::thread second_half;
    try {
        second_half = std::thread([&] {
            try {
                work(middle, count);
            } catch (...) {
                second_problem = std::current_exception();
            }
        });
    } catch (const std::system_error&) {
        // No thread to be had (out of threads or address space): both halves here, in order.
        work(0, count);
        return;
    }
    std::exception_ptr first_problem;
    try {
        work(0, middle);
    } catch (...) {
        first_problem = std::current_exception();
    }
    second_half.join();
    if (first_problem)
        std::rethrow_exception(first_problem);
    if (second_problem)
        std::rethrow_exception(second_problem);
}

} // namespace apcs
