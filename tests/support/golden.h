#pragma once

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace apcs::test {

// Where a mismatching output is kept beside its golden file, for a diff: screens.txt →
// screens.received.txt, inb004.dat → inb004.dat.received.txt (git ignores *.received.txt).
inline std::filesystem::path received_path(const std::filesystem::path& golden)
{
    std::filesystem::path received = golden;
    if (golden.extension() == ".txt")
        return received.replace_extension(".received.txt");
    return received += ".received.txt";
}

// Compares `actual` with the approved file tests/golden/NAME. On a mismatch `actual` is written to
// received_path(NAME), so that the failure is a diff; on a match a stale one is removed. Approving
// is explicit: run the tests with APCS_APPROVE=1 to (re)write the golden files, then review them
// with git diff.
inline void check_golden(const std::string& name, const std::string& actual)
{
    const std::filesystem::path file = std::filesystem::path(APCS_SOURCE_DIR) / "tests" / "golden" / name;
    const std::filesystem::path received = received_path(file);
    std::error_code ignored;
    if (std::getenv("APCS_APPROVE") != nullptr) {
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << actual;
        std::filesystem::remove(received, ignored);
        WARN("approved " << file.string());
        return;
    }
    const bool exists = std::filesystem::exists(file);
    const bool matches = exists && read_all(file) == actual;
    if (matches) {
        std::filesystem::remove(received, ignored);
    } else {
        std::filesystem::create_directories(received.parent_path(), ignored);
        std::ofstream(received, std::ios::binary) << actual;
    }
    INFO("golden file " << file.string() << (exists ? " differs" : " is missing") << "; the output is in "
                        << received.string() << " (diff them; APCS_APPROVE=1 rewrites the golden file)");
    REQUIRE(matches);
}

} // namespace apcs::test
