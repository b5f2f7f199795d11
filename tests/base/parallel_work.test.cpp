#include "apcs/base/parallel_work.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <new>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace apcs;

TEST_CASE("every index is worked on exactly once, by any number of workers", "[base][parallel]")
{
    for (const std::size_t workers : {1u, 2u, 8u}) {
        std::vector<std::atomic<int>> calls(100);
        for_each_index_in_parallel(calls.size(), workers, [&](std::size_t index) { ++calls[index]; });
        for (const std::atomic<int>& count : calls)
            CHECK(count == 1);
    }
}

TEST_CASE("an allocation failure in a worker reaches the caller instead of ending the program", "[base][parallel]")
{
    const auto fail_at_five = [](std::size_t index) {
        if (index == 5)
            throw std::bad_alloc();
    };
    CHECK_THROWS_AS(for_each_index_in_parallel(1000, 4, fail_at_five), std::bad_alloc);
}

TEST_CASE("split across cores covers every index once, in halves or whole", "[base][parallel]")
{
    for (const std::size_t worth_a_thread : {1u, 1000u}) {
        std::vector<std::atomic<int>> calls(100);
        split_across_cores(calls.size(), worth_a_thread, [&](std::size_t first, std::size_t end) {
            for (std::size_t index = first; index < end; ++index)
                ++calls[index];
        });
        for (const std::atomic<int>& count : calls)
            CHECK(count == 1);
    }
}

TEST_CASE("an exception in either half of a split reaches the caller once both halves have ended",
          "[base][parallel]")
{
    for (const std::size_t failing_index : {0u, 99u}) {
        std::atomic<int> halves_ended{0};
        const auto fail_in_one_half = [&](std::size_t first, std::size_t end) {
            ++halves_ended;
            if (first <= failing_index && failing_index < end)
                throw std::runtime_error("failed");
        };
        CHECK_THROWS_AS(split_across_cores(100, 1, fail_in_one_half), std::runtime_error);
        // Both halves run (each on its own core) when the machine has two; else the work is one call.
        CHECK(halves_ended == (std::thread::hardware_concurrency() >= 2 ? 2 : 1));
    }
}
