#include "apcs/base/parallel_work.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace apcs {

namespace {

// What each thread of one piece of work threw, kept until all have ended: the one place where an
// exception is caught on a thread and handed back to the thread that started the work.
class ThreadProblems {
public:
    explicit ThreadProblems(std::size_t threads) : m_problems(threads) {}

    // Runs task as thread number `thread`; what it throws is kept, not let out.
    void run(std::size_t thread, const std::function<void()>& task) noexcept
    {
        try {
            task();
        } catch (...) {
            m_problems[thread] = std::current_exception();
        }
    }

    // Called once every thread has ended: the lowest-numbered thread's exception, if any.
    void rethrow_first() const
    {
        for (const std::exception_ptr& problem : m_problems)
            if (problem)
                std::rethrow_exception(problem);
    }

private:
    // One slot per thread: each thread writes only its own.
    std::vector<std::exception_ptr> m_problems;
};

// Runs task(thread) for the threads 0 … threads − 1, this one as number 0, and returns once all
// have ended, with how many started (this one included): a thread that cannot be started (out of
// threads or address space) is not, and its number's work is left to the caller. Rethrows the
// lowest-numbered thread's exception.
std::size_t run_on_threads(std::size_t threads, const std::function<void(std::size_t thread)>& task)
{
    ThreadProblems problems(threads);
    std::size_t started = 1;
    {
        std::vector<std::jthread> helpers;
        try {
            for (std::size_t thread = 1; thread < threads; ++thread) {
                helpers.emplace_back([&, thread] { problems.run(thread, [&] { task(thread); }); });
                ++started;
            }
        } catch (const std::system_error&) {
            // The threads started do their numbers' work; the caller sees how many there were.
        }
        problems.run(0, [&] { task(0); });
    }
    problems.rethrow_first();
    return started;
}

} // namespace

void split_across_cores(std::size_t count, std::size_t worth_a_thread,
                        const std::function<void(std::size_t first, std::size_t end)>& work)
{
    if (count < 2 * worth_a_thread || std::thread::hardware_concurrency() < 2) {
        work(0, count);
        return;
    }
    const std::size_t middle = count / 2;
    const std::size_t started =
        run_on_threads(2, [&](std::size_t thread) { thread == 0 ? work(0, middle) : work(middle, count); });
    if (started < 2)
        work(middle, count);
}

void for_each_index_in_parallel(std::size_t count, std::size_t workers, const std::function<void(std::size_t)>& work)
{
    std::atomic<std::size_t> next{0};
    const auto take_indices = [&](std::size_t) {
        try {
            for (std::size_t index = next++; index < count; index = next++)
                work(index);
        } catch (...) {
            next = count;
            throw;
        }
    };
    // The threads started share the indices, however many could be.
    run_on_threads(std::max<std::size_t>(1, std::min(workers, count)), take_indices);
}

} // namespace apcs
