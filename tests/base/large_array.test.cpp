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

namespace {
struct AdviceAsked {
    void* storage = nullptr;
    std::size_t bytes = 0;
    int times = 0;
};
AdviceAsked advice_asked;
void record_advice(void* storage, std::size_t bytes)
{
    advice_asked = {storage, bytes, advice_asked.times + 1};
}
} // namespace

TEST_CASE("huge pages are asked for on the whole 2 MB-aligned storage of a large array, on any kernel",
          "[base][large_array]")
{
    // The kernel's answer is seen above where it has transparent huge pages; the asking, here, on
    // every kernel (one without huge pages shows no "hg" flag whatever was asked).
    advice_asked = {};
    const std::size_t bytes = large_array::huge_page_bytes * 2 + 1;
    void* storage = large_array::allocate(bytes, alignof(double), record_advice);
    CHECK(advice_asked.times == 1);
    CHECK(advice_asked.storage == storage);
    CHECK(advice_asked.bytes == large_array::huge_page_bytes * 3);
    CHECK(reinterpret_cast<std::uintptr_t>(storage) % large_array::huge_page_bytes == 0);
    large_array::deallocate(storage, bytes, alignof(double));

    void* small = large_array::allocate(1000, alignof(double), record_advice);
    CHECK(advice_asked.times == 1); // a small array is plain new: nothing asked
    large_array::deallocate(small, 1000, alignof(double));
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
