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

} // namespace

void split_across_cores(std::size_t count, std::size_t worth_a_thread,
                        const std::function<void(std::size_t first, std::size_t end)>& work)
{
    if (count < 2 * worth_a_thread || std::thread::hardware_concurrency() < 2) {
        work(0, count);
        return;
    }
    const std::size_t middle = count / 2;
    ThreadProblems problems(2);
    std::jthread second_half;
    try {
        second_half = std::jthread([&] { problems.run(1, [&] { work(middle, count); }); });
    } catch (const std::system_error&) {
        work(0, count);
        return;
    }
    problems.run(0, [&] { work(0, middle); });
    second_half.join();
    problems.rethrow_first();
}

void for_each_index_in_parallel(std::size_t count, std::size_t workers, const std::function<void(std::size_t)>& work)
{
    std::atomic<std::size_t> next{0};
    const auto take_indices = [&] {
        try {
            for (std::size_t index = next++; index < count; index = next++)
                work(index);
        } catch (...) {
            next = count;
            throw;
        }
    };
    const std::size_t threads = std::max<std::size_t>(1, std::min(workers, count));
    ThreadProblems problems(threads);
    {
        std::vector<std::jthread> helpers;
        try {
            for (std::size_t thread = 1; thread < threads; ++thread)
                helpers.emplace_back([&, thread] { problems.run(thread, take_indices); });
        } catch (const std::system_error&) {
            // The threads started share the indices with this one.
        }
        problems.run(0, take_indices);
    }
    problems.rethrow_first();
}

} // namespace apcs
