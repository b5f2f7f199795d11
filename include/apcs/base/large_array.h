#pragma once

#include <cstddef>
#include <new>
#include <vector>

// Storage for arrays of many megabytes (a path of 10^6 control points is 56 MB) in the kernel's
// 2 MB pages where it offers them (transparent huge pages, "madvise" mode included). A pass over
// such an array in 4 KB pages walks 14,000 page-table entries; after the program has waited for a
// key, on a virtual machine those walks are cold and a key's pass over 10^6 points took 5-10x as
// long as the same pass done at once (PERFORMANCE.md 9i). Smaller arrays are plain new/delete.
namespace apcs {

namespace large_array {
// From this size on an array gets its own 2 MB-aligned storage, advised for huge pages.
inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

// What asks the kernel for huge pages on `bytes` at `storage` (madvise MADV_HUGEPAGE; a test gives
// its own, to see the asking on a kernel that has no huge pages to give).
using HugePageAdvice = void (*)(void* storage, std::size_t bytes);
void advise_huge_pages(void* storage, std::size_t bytes);

void* allocate(std::size_t bytes, std::size_t alignment, HugePageAdvice advise = advise_huge_pages);
void deallocate(void* storage, std::size_t bytes, std::size_t alignment) noexcept;
} // namespace large_array

template <class T>
struct LargeArrayAllocator {
    using value_type = T;

    LargeArrayAllocator() = default;
    template <class U>
    constexpr LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept
    {
    }

    T* allocate(std::size_t count)
    {
        if (count > static_cast<std::size_t>(-1) / sizeof(T))
            throw std::bad_array_new_length();
        return static_cast<T*>(large_array::allocate(count * sizeof(T), alignof(T)));
    }
    void deallocate(T* storage, std::size_t count) noexcept
    {
        large_array::deallocate(storage, count * sizeof(T), alignof(T));
    }

    template <class U>
    friend bool operator==(const LargeArrayAllocator&, const LargeArrayAllocator<U>&) noexcept
    {
        return true;
    }
};

// A vector of many megabytes (a long path's per-point and per-segment numbers) in huge pages.
template <class T>
using LargeArray = std::vector<T, LargeArrayAllocator<T>>;

} // namespace apcs
