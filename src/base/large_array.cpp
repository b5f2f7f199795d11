#include "apcs/base/large_array.h"

#include <sys/mman.h>

#include <cstdlib>

namespace apcs::large_array {

namespace {

std::size_t whole_huge_pages(std::size_t bytes)
{
    return (bytes + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
}

} // namespace

// Advice only: where the kernel has no huge pages to give, the array is in 4 KB pages as before.
void advise_huge_pages(void* storage, std::size_t bytes) { (void)madvise(storage, bytes, MADV_HUGEPAGE); }

void* allocate(std::size_t bytes, std::size_t alignment, HugePageAdvice advise)
{
    if (bytes < huge_page_bytes)
        return ::operator new(bytes, std::align_val_t{alignment});
    if (bytes > static_cast<std::size_t>(-1) - huge_page_bytes)
        throw std::bad_alloc(); // rounding up to whole pages would wrap around to a few bytes
    const std::size_t whole = whole_huge_pages(bytes);
    void* storage = std::aligned_alloc(huge_page_bytes, whole);
    if (storage == nullptr)
        throw std::bad_alloc();
    advise(storage, whole);
    return storage;
}

void deallocate(void* storage, std::size_t bytes, std::size_t alignment) noexcept
{
    if (bytes < huge_page_bytes)
        ::operator delete(storage, std::align_val_t{alignment});
    else
        std::free(storage);
}

} // namespace apcs::large_array
