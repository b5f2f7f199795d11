#include "apcs/formats/dat_file.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/text_lines.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

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
        // The file read a block at a time and parsed as it comes: what reading it whole gives,
        // error for error (a NUL byte is refused by the reading, before any line).
        const Expected<Graphic> read = read_key_frame(entry.path());
        const Expected<DatFile> read_whole = read_dat_file(entry.path());
        REQUIRE(read.has_value() == read_whole.has_value());
        if (read)
            REQUIRE(read->point_count() == read_whole->point_count());
        else
            REQUIRE(read.error().to_string() == read_whole.error().to_string());
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

TEST_CASE("text fed in pieces of any size gives the lines and the problem of the whole text", "[formats][fuzz]")
{
    using Seen = std::vector<std::pair<int, std::string>>;
    const auto read_whole = [](std::string_view text, Seen& seen) {
        return for_each_data_line(text, "t.dat", [&seen](int line, std::string_view content) -> Expected<void> {
            seen.emplace_back(line, std::string(content));
            return ok;
        });
    };
    std::vector<std::string> texts{"\xEF\xBB\xBF" "1 2\r\n3 4\r", "a\r\r\nb\rc", "x\n\x1A\r\n", "x\ny\x1Az", "\xEF\xBB", ""};
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "tests/fuzz/dat_reader"))
        texts.push_back(test::read_all(entry.path()));
    for (const std::string& text : texts) {
        Seen whole;
        const Expected<void> whole_outcome = read_whole(text, whole);
        for (const std::size_t piece : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{7}, std::size_t{64}}) {
            CAPTURE(text, piece);
            Seen pieces;
            DataLineReader reader("t.dat", [&pieces](int line, std::string_view content) -> Expected<void> {
                pieces.emplace_back(line, std::string(content));
                return ok;
            });
            Expected<void> outcome = ok;
            for (std::size_t at = 0; at < text.size() && outcome; at += piece)
                outcome = reader.feed(std::string_view(text).substr(at, piece));
            if (outcome)
                outcome = reader.finish();
            REQUIRE(pieces == whole);
            REQUIRE(outcome.has_value() == whole_outcome.has_value());
            if (!outcome)
                REQUIRE(outcome.error().to_string() == whole_outcome.error().to_string());
        }
    }
}
