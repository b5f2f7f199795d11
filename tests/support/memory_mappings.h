#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace apcs::test {

// The VmFlags line of the mapping in /proc/self/smaps that holds `address` (" hg": advised for
// huge pages), or "" when none holds it.
inline std::string vm_flags_at(const void* address)
{
    const auto at = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t from = 0;
        std::uintptr_t to = 0;
        char dash = 0;
        std::istringstream range(line);
        if (range >> std::hex >> from >> dash >> to && dash == '-' && line.find(' ') > line.find('-'))
            inside = from <= at && at < to;
        else if (inside && line.rfind("VmFlags:", 0) == 0)
            return line;
    }
    return {};
}

inline bool kernel_has_huge_pages() { return std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"); }

// Checks that the memory at `address` is advised for huge pages, where the kernel has them: on a
// kernel without, no flag can show it, and the asking itself is checked with a fake advice
// (large_array.test.cpp).
inline void check_advised_for_huge_pages(const void* address)
{
    if (!kernel_has_huge_pages())
        return;
    const std::string flags = vm_flags_at(address);
    INFO(flags);
    CHECK(flags.find(" hg") != std::string::npos);
}

} // namespace apcs::test
