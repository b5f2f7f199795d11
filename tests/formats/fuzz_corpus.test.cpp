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

TEST_CASE("a key frame read straight into positions is the graphic of the .dat file, error for error",
          "[formats][fuzz]")
{
    std::size_t accepted = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "tests/fuzz/dat_reader")) {
        CAPTURE(entry.path().filename().string());
        const std::string text = test::read_all(entry.path());
        const Expected<DatFile> file = parse_dat(text, "k.dat", 2);
        const Expected<Graphic> graphic = parse_key_frame(text, "k.dat");
        REQUIRE(file.has_value() == graphic.has_value());
        if (!file) {
            REQUIRE(graphic.error().to_string() == file.error().to_string());
            continue;
        }
        ++accepted;
        const Graphic expected = graphic_from(*file);
        REQUIRE(graphic->parts.size() == expected.parts.size());
        for (std::size_t i = 0; i < expected.parts.size(); ++i) {
            REQUIRE(graphic->parts[i].name == expected.parts[i].name);
            REQUIRE(graphic->parts[i].closure == expected.parts[i].closure);
            REQUIRE(graphic->parts[i].points == expected.parts[i].points);
        }
    }
    REQUIRE(accepted > 10);
}
