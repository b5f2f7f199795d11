#include "apcs/formats/parallel_work.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <new>
#include <vector>

using namespace apcs;

TEST_CASE("every index is worked on exactly once, by any number of workers", "[formats][parallel]")
{
    for (const std::size_t workers : {1u, 2u, 8u}) {
        std::vector<std::atomic<int>> calls(100);
        for_each_index_in_parallel(calls.size(), workers, [&](std::size_t index) { ++calls[index]; });
        for (const std::atomic<int>& count : calls)
            CHECK(count == 1);
    }
}

TEST_CASE("an allocation failure in a worker reaches the caller instead of ending the program", "[formats][parallel]")
{
    const auto fail_at_five = [](std::size_t index) {
        if (index == 5)
            throw std::bad_alloc();
    };
    CHECK_THROWS_AS(for_each_index_in_parallel(1000, 4, fail_at_five), std::bad_alloc);
}
