#include "apcs/formats/key_script.h"
#include "apcs/formats/script_input.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/stat.h>

using namespace apcs;
namespace fs = std::filesystem;

namespace {

const fs::path data = fs::path(APCS_SOURCE_DIR) / "data";

// Every captioned script the data folder ships that is not an exercise: the lessons and the
// examples' sessions, each played in its own example's folder.
const std::vector<std::string> lessons = {
    "n-to-l/lesson.keys",         "n-to-l/lesson-waypoints.keys", "n-to-l/lesson-continuity.keys",
    "n-to-l/lesson-bias.keys",    "n-to-l/lesson-regions.keys",   "n-to-l/lesson-acceleration.keys",
    "n-to-l/lesson-surface.keys", "n-to-l/session.keys",          "stick/session.keys",
    "snake-apple/session.keys",
};

KeyScript parsed(const fs::path& script)
{
    Expected<KeyScript> parsed = parse_captioned_key_script(test::read_all(script), script.string());
    REQUIRE(parsed);
    return std::move(*parsed);
}

test::CommandRun replay(const fs::path& script, const fs::path& folder)
{
    return test::run_apcs({"--keys", script.string(), "--workdir", folder.string()});
}

// The names in `folder`, sorted, each with its size: what a refused replay must leave as it was.
std::vector<std::string> listing(const fs::path& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string() + " " +
                        std::to_string(entry.is_regular_file() ? entry.file_size() : 0));
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

TEST_CASE("every shipped lesson names its inputs without checksums, and they are all its replay reads",
          "[cli][lesson][inputs]")
{
    const std::string lesson = GENERATE(from_range(lessons));
    CAPTURE(lesson);
    const KeyScript script = parsed(data / lesson);
    REQUIRE_FALSE(script.inputs.empty());
    // A folder holding the named inputs and nothing else plays the whole lesson.
    const test::TempFolder folder;
    for (const ScriptInput& input : script.inputs) {
        REQUIRE_FALSE(input.crc32);
        fs::copy_file(data / fs::path(lesson).parent_path() / input.name, folder / input.name);
    }
    const test::CommandRun played = replay(data / lesson, folder.path());
    INFO(played.err);
    REQUIRE(played.status == 0);
}

TEST_CASE("a lesson in an empty folder, or in a folder without one of its inputs, is refused before any key with "
          "exit 1, the INPUT line and what to copy, and writes nothing",
          "[cli][lesson][inputs]")
{
    const std::string lesson = GENERATE(from_range(lessons));
    CAPTURE(lesson);
    const KeyScript script = parsed(data / lesson);
    const test::TempFolder folder;
    const ScriptInput missing = script.inputs.back();
    SECTION("an empty folder")
    {
    }
    SECTION("a folder with all but the last input")
    {
        for (const ScriptInput& input : script.inputs)
            if (input.name != missing.name)
                fs::copy_file(data / fs::path(lesson).parent_path() / input.name, folder / input.name);
    }
    const ScriptInput& first_missing = fs::exists(folder / script.inputs.front().name) ? missing : script.inputs.front();
    const std::vector<std::string> before = listing(folder.path());
    const test::CommandRun refused = replay(data / lesson, folder.path());
    REQUIRE(refused.status == 1);
    REQUIRE(refused.out.empty());
    REQUIRE(refused.err == (data / lesson).string() + ":" + std::to_string(first_missing.line_number) + ": " +
                               first_missing.name + " is missing from the work folder " + folder.path().string() +
                               "; expected the lesson's input: copy the lesson's files into the work folder again\n");
    REQUIRE(listing(folder.path()) == before);
}

TEST_CASE("a lesson's input that is a FIFO or a symbolic link is refused without being opened", "[cli][lesson][inputs]")
{
    const test::TempFolder folder;
    for (const char* name : {"key1.dat", "key2.dat"})
        fs::copy_file(data / "n-to-l" / name, folder / name);
    const fs::path lesson = data / "n-to-l" / "lesson-bias.keys";
    const int way_line = parsed(lesson).inputs.back().line_number;
    std::string kind;
    SECTION("a FIFO, which nobody writes")
    {
        REQUIRE(::mkfifo((folder / "way1.dat").c_str(), 0600) == 0);
        kind = "a FIFO";
    }
    SECTION("a symbolic link to the right file")
    {
        fs::create_symlink(data / "n-to-l" / "way1.dat", folder / "way1.dat");
        kind = "a symbolic link";
    }
    const test::CommandRun refused = replay(lesson, folder.path());
    REQUIRE(refused.status == 1);
    REQUIRE(refused.err == lesson.string() + ":" + std::to_string(way_line) + ": way1.dat is " + kind +
                               "; expected the lesson's input, a regular file of its own: copy the lesson's files "
                               "into the work folder again\n");
}

TEST_CASE("a lesson plays in a folder where an earlier lesson rewrote its input", "[cli][lesson][inputs]")
{
    const test::TempFolder folder;
    for (const auto& entry : fs::directory_iterator(data / "n-to-l"))
        fs::copy_file(entry.path(), folder / entry.path().filename().string());
    const std::string shipped = test::read_all(folder / "way1.dat");
    REQUIRE(replay(folder / "lesson-surface.keys", folder.path()).status == 0); // accepts way1.dat as it is
    REQUIRE(test::read_all(folder / "way1.dat") != shipped);
    const test::CommandRun later = replay(folder / "lesson-bias.keys", folder.path());
    INFO(later.err);
    REQUIRE(later.status == 0);
}

TEST_CASE("an exercise's INPUT line without its CRC32 is refused: only a lesson names an input by its presence",
          "[formats][exercises][inputs]")
{
    const Expected<KeyScript> exercise =
        parse_captioned_key_script("INPUT key1.dat CRC32 de215594\nINPUT way1.dat\nSTART\nGOAL VALUE TENSION 0.4 0.6\n",
                                   "e.keys");
    REQUIRE_FALSE(exercise);
    REQUIRE(exercise.error().to_string() ==
            "e.keys:2: INPUT way1.dat without its CRC32 in an exercise (a script with GOAL lines); expected INPUT NAME "
            "CRC32 XXXXXXXX, the file's checksum");
    const Expected<KeyScript> lesson = parse_captioned_key_script("INPUT way1.dat ; the path\nSTART\n;; a caption\n4\n",
                                                                  "l.keys");
    REQUIRE(lesson);
    REQUIRE(lesson->inputs == std::vector<ScriptInput>{{"way1.dat", std::nullopt, 1}});
    REQUIRE(input_line(lesson->inputs[0]) == "INPUT way1.dat");
}
