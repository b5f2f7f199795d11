#include "apcs/base/large_array.h"
#include "support/memory_mappings.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

using namespace apcs;

namespace {

struct Point56 {
    double values[7];
};

} // namespace

TEST_CASE("an array of 2 MB or more is on a 2 MB boundary, advised for the kernel's huge pages", "[base][large_array]")
{
    std::vector<Point56, LargeArrayAllocator<Point56>> points(1'000'000);
    const auto address = reinterpret_cast<std::uintptr_t>(points.data());
    CHECK(address % large_array::huge_page_bytes == 0);
    test::check_advised_for_huge_pages(points.data() + points.size() / 2);
}

TEST_CASE("an array that grows past 2 MB keeps its values, and a small one is ordinary", "[base][large_array]")
{
    std::vector<Point56, LargeArrayAllocator<Point56>> points;
    constexpr std::size_t past_two_megabytes = (large_array::huge_page_bytes / sizeof(Point56)) * 3;
    for (std::size_t k = 0; k < past_two_megabytes; ++k)
        points.push_back({{static_cast<double>(k)}});
    REQUIRE(points.size() == past_two_megabytes);
    for (std::size_t k = 0; k < points.size(); k += 997)
        CHECK(points[k].values[0] == static_cast<double>(k));
    std::vector<Point56, LargeArrayAllocator<Point56>> few(3, Point56{{1.5}});
    few.shrink_to_fit();
    CHECK(few[2].values[0] == 1.5);
    CHECK(LargeArrayAllocator<Point56>{} == LargeArrayAllocator<int>{});
}

TEST_CASE("an array too large for the address space is refused, not wrapped around", "[base][large_array]")
{
    LargeArrayAllocator<Point56> allocator;
    CHECK_THROWS_AS(allocator.allocate(static_cast<std::size_t>(-1) / sizeof(Point56) + 1), std::bad_array_new_length);
    CHECK_THROWS_AS(allocator.allocate(static_cast<std::size_t>(-1) / sizeof(Point56)), std::bad_alloc);
}
