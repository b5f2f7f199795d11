#pragma once

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace apcs::test {

// Compares `actual` with the approved file tests/golden/NAME. Approving is explicit: run the tests
// with APCS_APPROVE=1 to (re)write the golden files, then review them with git diff.
inline void check_golden(const std::string& name, const std::string& actual)
{
    const std::filesystem::path file = std::filesystem::path(APCS_SOURCE_DIR) / "tests" / "golden" / name;
    if (std::getenv("APCS_APPROVE") != nullptr) {
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << actual;
        WARN("approved " << file.string());
        return;
    }
    INFO("golden file " << file.string() << " (APCS_APPROVE=1 rewrites it)");
    REQUIRE(std::filesystem::exists(file));
    REQUIRE(read_all(file) == actual);
}

} // namespace apcs::test
