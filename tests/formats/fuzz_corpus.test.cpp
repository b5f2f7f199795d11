#include "apcs/formats/dat_file.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace apcs;

TEST_CASE("every input of the .dat fuzzing corpus is read or refused, and what is read writes back alike",
          "[formats][fuzz]")
{
    std::size_t inputs = 0;
    std::size_t accepted = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "tests/fuzz/dat_reader")) {
        const std::string text = test::read_all(entry.path());
        const Expected<DatFile> file = parse_dat(text, "corpus.dat", 0);
        ++inputs;
        if (!file) {
            REQUIRE_FALSE(file.error().message.empty());
            continue;
        }
        ++accepted;
        const Expected<DatFile> again = parse_dat(format_dat(*file), "again.dat", 0);
        REQUIRE(again.has_value());
        REQUIRE(again->point_count() == file->point_count());
    }
    REQUIRE(inputs > 100);
    REQUIRE(accepted > 0);
}
