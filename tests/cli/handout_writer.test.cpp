#include "apcs/lesson/handout.h"
#include "apcs/formats/key_event.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace apcs;

namespace {

std::string read_all(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::filesystem::path source(const std::string& name) { return std::filesystem::path(APCS_SOURCE_DIR) / name; }

void copy_n_to_l(const test::TempFolder& folder)
{
    for (const auto& entry : std::filesystem::directory_iterator(source("data/n-to-l")))
        std::filesystem::copy_file(entry.path(), folder / entry.path().filename().string());
}

// The screens of an approved captions file (tests/golden/lessons/…), one per "=== N: CAPTION" line.
std::vector<std::string> golden_caption_screens(const std::string& name)
{
    std::istringstream golden(read_all(source("tests/golden/lessons/" + name)));
    std::vector<std::string> screens;
    for (std::string line; std::getline(golden, line);) {
        if (line.starts_with("=== "))
            screens.emplace_back();
        else if (!screens.empty())
            screens.back() += line + '\n';
    }
    return screens;
}

// A PNG's width and height from its IHDR chunk.
std::pair<unsigned, unsigned> png_size(const std::string& png)
{
    REQUIRE(png.size() > 24);
    REQUIRE(png.substr(1, 3) == "PNG");
    const auto big_endian = [&png](std::size_t at) {
        unsigned value = 0;
        for (std::size_t byte = at; byte < at + 4; ++byte)
            value = value << 8 | static_cast<unsigned char>(png[byte]);
        return value;
    };
    return {big_endian(16), big_endian(20)};
}

std::vector<std::string> file_names(const std::filesystem::path& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

test::CommandRun lesson_handout(const test::TempFolder& folder, const std::filesystem::path& handout)
{
    return test::run_apcs({"--keys", (folder / "lesson.keys").string(), "--workdir", folder.path().string(),
                           "--glyphs", "ascii", "--handout", handout.string()});
}

} // namespace

TEST_CASE("a handout (--handout) holds each caption of the N to L lesson as NN-STEP.png (720x522) and its approved screen "
          "as NN-STEP.txt",
          "[cli][handout][teaching]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    const auto result = lesson_handout(folder, folder / "handout");
    REQUIRE(result.status == 0);
    const Expected<KeyScript> script = parse_captioned_key_script(read_all(source("data/n-to-l/lesson.keys")), "lesson");
    REQUIRE(script);
    const std::vector<std::string> screens = golden_caption_screens("n-to-l/lesson-captions-ascii.txt");
    REQUIRE(screens.size() == script->captions.size());
    std::vector<std::string> expected;
    for (std::size_t index = 0; index < screens.size(); ++index) {
        const std::string stem = handout_file_stem(static_cast<int>(index) + 1, script->captions.size(), script->captions[index].text);
        CAPTURE(stem);
        expected.push_back(stem + ".png");
        expected.push_back(stem + ".txt");
        REQUIRE(read_all(folder / ("handout/" + stem + ".txt")) == screens[index]);
        REQUIRE(png_size(read_all(folder / ("handout/" + stem + ".png"))) == std::pair{720u, 522u});
    }
    std::sort(expected.begin(), expected.end());
    REQUIRE(file_names(folder / "handout") == expected);
    REQUIRE(expected.front() == "01-the-key-frames-the-view-face-on.png");
}

TEST_CASE("a handout's folder (--handout) is made one level deep, before the session starts", "[cli][handout]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    const auto result = lesson_handout(folder, folder / "no/handout");
    REQUIRE(result.status == 1);
    REQUIRE(result.err == (folder / "no/handout").string() + ": cannot be made: " + (folder / "no").string() +
                              " is not a folder (--out makes one level, not its parents)\n");
    REQUIRE_FALSE(std::filesystem::exists(folder / "ani1.dat"));
    REQUIRE(test::run_apcs({"--handout", (folder / "h").string()}).status == 2);
}

TEST_CASE("a handout's pages (--handout) are replaced as pictures are: same content untouched, changed kept as .bak",
          "[cli][handout]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    REQUIRE(lesson_handout(folder, folder / "handout").status == 0);
    const std::filesystem::path page = folder / "handout/01-the-key-frames-the-view-face-on";
    std::ofstream(page.string() + ".txt", std::ios::binary) << "old text\n";
    std::ofstream(page.string() + ".png", std::ios::binary) << "old picture\n";
    const auto first_written = std::filesystem::last_write_time(folder / "handout/02-w-opens-the-waypoint-editor-i.png");
    REQUIRE(lesson_handout(folder, folder / "handout").status == 0);
    REQUIRE(read_all(page.string() + ".bak") == "old picture\n");
    REQUIRE(read_all(page.string() + ".b01") == "old text\n");
    REQUIRE(read_all(page.string() + ".txt").starts_with("Please keyin the KEY1 filename!\n"));
    REQUIRE(std::filesystem::last_write_time(folder / "handout/02-w-opens-the-waypoint-editor-i.png") == first_written);
}
