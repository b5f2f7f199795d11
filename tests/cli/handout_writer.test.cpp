#include "apcs/lesson/handout.h"
#include "apcs/lesson/handout_index.h"
#include "apcs/formats/key_script.h"

#include "support/png_pixels.h"
#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>

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

TEST_CASE("a handout (--handout) holds each caption of the N to L lesson as NN-STEP.png (720x522) and the approved screen "
          "once its keys have played as NN-STEP.txt",
          "[cli][handout][teaching]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    const auto result = lesson_handout(folder, folder / "handout");
    REQUIRE(result.status == 0);
    const Expected<KeyScript> script = parse_captioned_key_script(read_all(source("data/n-to-l/lesson.keys")), "lesson");
    REQUIRE(script);
    // The approved screens are each caption beside the screen its keys made.
    const std::vector<std::string> screens = golden_caption_screens("n-to-l/lesson-captions-ascii.txt");
    REQUIRE(screens.size() == script->captions.size());
    std::vector<std::string> expected = {"index.html"};
    for (std::size_t index = 0; index < screens.size(); ++index) {
        const std::string& caption = script->captions[index].text;
        const std::string stem = handout_file_stem(static_cast<int>(index) + 1, script->captions.size(), caption);
        CAPTURE(stem);
        expected.push_back(stem + ".png");
        expected.push_back(stem + ".txt");
        REQUIRE(read_all(folder / ("handout/" + stem + ".txt")) == screens[index]);
        REQUIRE(png_size(read_all(folder / ("handout/" + stem + ".png"))) == std::pair{720u, 522u});
    }
    std::sort(expected.begin(), expected.end());
    REQUIRE(file_names(folder / "handout") == expected);
    REQUIRE(expected.front() == "01-w-i-a-control-point-halfway.png");
    // Issue 42: "T shows the tangents" shows their numbers.
    REQUIRE(read_all(folder / "handout/02-t-shows-the-tangents-to-scale-dd.txt").find(" point 2  DS 0.00 0.00 5.00") !=
            std::string::npos);
}

TEST_CASE("a handout's index.html shows every page's picture with its caption in the script's order",
          "[cli][handout][teaching]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    REQUIRE(lesson_handout(folder, folder / "handout").status == 0);
    const Expected<KeyScript> script = parse_captioned_key_script(read_all(source("data/n-to-l/lesson.keys")), "lesson");
    REQUIRE(script);
    const std::string html = read_all(folder / "handout/index.html");
    REQUIRE(html.find("<title>lesson.keys</title>") != std::string::npos);
    std::size_t after = 0;
    for (std::size_t index = 0; index < script->captions.size(); ++index) {
        const std::string& caption = script->captions[index].text;
        const std::string picture = handout_file_stem(static_cast<int>(index) + 1, script->captions.size(), caption) + ".png";
        CAPTURE(picture);
        REQUIRE(std::filesystem::is_regular_file(folder / "handout" / picture));
        const std::size_t at = html.find("<img src=\"" + picture + "\"", after);
        REQUIRE(at != std::string::npos);
        const std::size_t said = html.find("<figcaption>" + std::to_string(index + 1) + ". " + html_escaped(caption) + "</figcaption>", at);
        REQUIRE(said != std::string::npos);
        after = said;
    }
}

TEST_CASE("a handout has no page of an empty prompt: a title caption before the first key gets none",
          "[cli][handout]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    std::ofstream(folder / "title.keys") << ";; Paths & <tangents>\n;; The key frames\nENTER ENTER\n";
    const auto result = test::run_apcs({"--keys", (folder / "title.keys").string(), "--workdir", folder.path().string(),
                                        "--glyphs", "ascii", "--handout", (folder / "handout").string()});
    REQUIRE(result.status == 0);
    REQUIRE(file_names(folder / "handout") ==
            std::vector<std::string>{"02-the-key-frames.png", "02-the-key-frames.txt", "index.html"});
    const std::string html = read_all(folder / "handout/index.html");
    REQUIRE(html.find("<figcaption>2. The key frames</figcaption>") != std::string::npos);
    REQUIRE(html.find("tangents") == std::string::npos);
    REQUIRE(html.find("<title>title.keys</title>") != std::string::npos);
}

TEST_CASE("a handout drawn for paper (--paper) is black on white: every pixel the monitor's inverted", "[cli][handout]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    REQUIRE(lesson_handout(folder, folder / "monitor").status == 0);
    const auto paper = test::run_apcs({"--keys", (folder / "lesson.keys").string(), "--workdir", folder.path().string(),
                                       "--glyphs", "ascii", "--handout", (folder / "paper").string(), "--paper"});
    REQUIRE(paper.status == 0);
    REQUIRE(file_names(folder / "paper") == file_names(folder / "monitor"));
    int pictures = 0;
    for (const std::string& name : file_names(folder / "monitor")) {
        if (!name.ends_with(".png"))
            continue;
        CAPTURE(name);
        ++pictures;
        const test::GreyPicture monitor = test::grey_picture(read_all(folder / "monitor" / name));
        const test::GreyPicture printed = test::grey_picture(read_all(folder / "paper" / name));
        REQUIRE(monitor.width == 720);
        REQUIRE(printed.width == monitor.width);
        REQUIRE(printed.height == monitor.height);
        // The monitor is mostly dark and the paper mostly white; what is lit on one is ink on the other.
        const auto half = static_cast<std::ptrdiff_t>(monitor.pixels.size() / 2);
        REQUIRE(std::count(monitor.pixels.begin(), monitor.pixels.end(), 0) > half);
        REQUIRE(std::count(printed.pixels.begin(), printed.pixels.end(), 255) > half);
        std::size_t inverted = 0;
        for (std::size_t at = 0; at < monitor.pixels.size(); ++at)
            inverted += printed.pixels[at] == 255 - monitor.pixels[at];
        REQUIRE(inverted == monitor.pixels.size());
        REQUIRE(read_all(folder / "paper" / (name.substr(0, name.size() - 4) + ".txt")) ==
                read_all(folder / "monitor" / (name.substr(0, name.size() - 4) + ".txt")));
    }
    REQUIRE(pictures == 7);
}

TEST_CASE("a run with --paper and no --handout is refused: exit 2 and what to give", "[cli][handout]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    const auto result = test::run_apcs({"--keys", (folder / "lesson.keys").string(), "--workdir", folder.path().string(),
                                        "--paper"});
    REQUIRE(result.status == 2);
    REQUIRE(result.err == "apcs: --paper draws the pages of a handout black on white; give --handout DIR\n");
    REQUIRE_FALSE(std::filesystem::exists(folder / "apcs.log"));
    REQUIRE(test::run_apcs({"path", (folder / "way1.dat").string(), "--paper"}).status == 2);
}

TEST_CASE("a handout folder that is a file or a FIFO, or an index.html that is a folder, is refused before the session",
          "[cli][handout]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    std::ofstream(folder / "notes.txt") << "mine\n";
    ::mkfifo((folder / "pipe").c_str(), 0644);
    std::filesystem::create_directories(folder / "hand/index.html");
    const auto file = lesson_handout(folder, folder / "notes.txt");
    REQUIRE(file.status == 1);
    REQUIRE(file.err == (folder / "notes.txt").string() + ": is not a folder; expected a folder for the handout (--handout)\n");
    REQUIRE(read_all(folder / "notes.txt") == "mine\n");
    const auto fifo = lesson_handout(folder, folder / "pipe");
    REQUIRE(fifo.status == 1);
    REQUIRE(fifo.err == (folder / "pipe").string() + ": is not a folder; expected a folder for the handout (--handout)\n");
    REQUIRE(std::filesystem::is_fifo(folder / "pipe"));
    const auto index = lesson_handout(folder, folder / "hand");
    REQUIRE(index.status == 1);
    REQUIRE(index.err.starts_with((folder / "hand/index.html").string() + ": "));
    REQUIRE(std::filesystem::is_directory(folder / "hand/index.html"));
    // Nothing ran: no session file, no page.
    REQUIRE_FALSE(std::filesystem::exists(folder / "ani1.dat"));
    REQUIRE_FALSE(std::filesystem::exists(folder / "apcs.log"));
    REQUIRE(file_names(folder / "hand") == std::vector<std::string>{"index.html"});
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
    const std::filesystem::path page = folder / "handout/01-w-i-a-control-point-halfway";
    std::ofstream(page.string() + ".txt", std::ios::binary) << "old text\n";
    std::ofstream(page.string() + ".png", std::ios::binary) << "old picture\n";
    const auto first_written = std::filesystem::last_write_time(folder / "handout/02-t-shows-the-tangents-to-scale-dd.png");
    REQUIRE(lesson_handout(folder, folder / "handout").status == 0);
    REQUIRE(read_all(page.string() + ".bak") == "old picture\n");
    REQUIRE(read_all(page.string() + ".b01") == "old text\n");
    REQUIRE(read_all(page.string() + ".txt").starts_with("+-----"));
    REQUIRE(std::filesystem::last_write_time(folder / "handout/02-t-shows-the-tangents-to-scale-dd.png") == first_written);
}

TEST_CASE("a handout goes only into a new or empty folder or an earlier handout's, and the user's files stay as they were",
          "[cli][handout][names]")
{
    const test::TempFolder folder;
    copy_n_to_l(folder);
    std::filesystem::create_directories(folder / "mine");
    std::ofstream(folder / "mine/index.html") << "<html>my course page</html>\n";
    std::ofstream(folder / "mine/index.bak") << "my older course page\n";
    const auto mine = lesson_handout(folder, folder / "mine");
    REQUIRE(mine.status == 1);
    REQUIRE(mine.err.starts_with((folder / "mine").string() + ": holds an index.html that is not a handout's; a handout is "
                                                              "written only into a new or empty folder"));
    REQUIRE(read_all(folder / "mine/index.bak") == "my older course page\n");
    REQUIRE(file_names(folder / "mine") == std::vector<std::string>{"index.bak", "index.html"});
    REQUIRE_FALSE(std::filesystem::exists(folder / "apcs.log"));

    REQUIRE(lesson_handout(folder, folder / "handout").status == 0);
    std::filesystem::copy_file(folder / "handout/01-w-i-a-control-point-halfway.png", folder / "handout/98-older.png");
    std::ofstream(folder / "handout/99-older.txt") << "an earlier, longer lesson's page\n";
    const auto again = lesson_handout(folder, folder / "handout");
    REQUIRE(again.status == 0);
    REQUIRE(again.err.ends_with("\napcs: " + (folder / "handout/98-older.png").string() + " to " +
                                (folder / "handout/99-older.txt").string() +
                                " (2 files) are from an earlier run (not rewritten)\n"));
    REQUIRE(std::filesystem::exists(folder / "handout/99-older.txt"));
    std::ofstream(folder / "handout/notes.txt") << "mine\n";
    const auto notes = lesson_handout(folder, folder / "handout");
    REQUIRE(notes.status == 1);
    REQUIRE(notes.err.starts_with((folder / "handout").string() + ": holds notes.txt, which is not a file of a handout; "));
}
