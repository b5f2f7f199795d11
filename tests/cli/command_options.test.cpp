#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

using apcs::test::run_apcs;

namespace {

// Each command's options as manual.txt section 14 lists them.
struct CommandOptions {
    std::vector<std::string> command; // {} is the session
    std::set<std::string> options;
};

const std::set<std::string> staff{"--tension", "--continuity", "--bias", "--accel"};
const std::set<std::string> curve{"--slopes", "--samples", "--spacing", "--inbetweens"};
const std::set<std::string> view{"--theta", "--phi", "--view"};
const std::set<std::string> pictures{"--png", "--png-raw", "--svg"};

std::set<std::string> joined(std::initializer_list<std::set<std::string>> sets)
{
    std::set<std::string> all;
    for (const auto& set : sets)
        all.insert(set.begin(), set.end());
    return all;
}

std::vector<CommandOptions> commands()
{
    return {
        {{}, joined({staff, curve, view, pictures, {"--delay", "--glyphs", "--pixels", "--step", "--workdir", "--keys", "--pace", "--record"}})},
        {{"path", "a.dat"}, joined({staff, curve, view, pictures, {"--print"}})},
        {{"fit", "a", "b", "c", "d"}, joined({staff, curve, view, pictures, {"--gif", "--delay", "--print", "--out"}})},
        {{"inbetween", "a", "b"},
         joined({view, pictures, {"--gif", "--delay", "--inbetweens", "--frames", "--law", "--pad", "--print", "--out"}})},
        {{"draw", "a.dat"}, joined({view, pictures})},
        {{"figures"}, joined({staff, curve, {"--workdir", "--out"}})},
        {{"play", "a.scn"},
         joined({staff, view, pictures, {"--slopes", "--samples", "--spacing", "--glyphs", "--pixels", "--gif", "--delay", "--print",
                                         "--out", "--tree"}})},
    };
}

std::string help_of(const std::vector<std::string>& command)
{
    std::vector<std::string> arguments;
    if (!command.empty())
        arguments.push_back(command.front());
    arguments.push_back("--help");
    return run_apcs(arguments).out;
}

} // namespace

TEST_CASE("every command refuses each option of another command with exit 2 and one line", "[cli]")
{
    std::set<std::string> every_option;
    for (const CommandOptions& command : commands())
        every_option.insert(command.options.begin(), command.options.end());
    for (const CommandOptions& command : commands()) {
        for (const std::string& option : every_option) {
            if (command.options.contains(option))
                continue;
            std::vector<std::string> arguments = command.command;
            arguments.push_back(option);
            arguments.push_back("1");
            CAPTURE(arguments);
            const auto result = run_apcs(arguments);
            CHECK(result.status == 2);
            CHECK(result.err.find("apcs: " + option + " is not an option of") == 0);
        }
    }
}

TEST_CASE("the session's --pixels takes auto, sixel, kitty and off, another word is exit 2 with the four named", "[cli][pixels]")
{
    for (const char* word : {"bogus", "sixels", "", "on"}) {
        CAPTURE(word);
        const auto result = run_apcs({"--pixels", word});
        CHECK(result.status == 2);
        CHECK(result.err.starts_with("apcs: --pixels: expected one of auto, sixel, kitty, off, found '"));
    }
}

TEST_CASE("every command's --help lists exactly its own options, without the parser's jargon", "[cli]")
{
    std::set<std::string> every_option;
    for (const CommandOptions& command : commands())
        every_option.insert(command.options.begin(), command.options.end());
    for (const CommandOptions& command : commands()) {
        const std::string help = help_of(command.command);
        CAPTURE(command.command, help);
        for (const std::string& option : every_option)
            CHECK((help.find("  " + option + " ") != std::string::npos ||
                   help.find("  " + option + "\n") != std::string::npos) == command.options.contains(option));
        for (const char* jargon : {"SPEC", "FLOAT", "TEXT", "INT", "Excludes", "REQUIRED", "1e+05"})
            CHECK(help.find(jargon) == std::string::npos);
    }
}

TEST_CASE("a picture is never written over an input of the run, by a link or a name without extension", "[cli]")
{
    const apcs::test::TempFolder folder;
    const std::string key = "0 0 0\n0 0 10\n";
    folder.write("key1.dat", key);
    folder.write("key2.dat", "0 5 0\n0 5 10\n");
    folder.write("k1", key);
    // A scene's drawing, known as an input only once the scene is read.
    folder.write("scene.scn", "FRAMES 2\nOBJECT a\nSHAPE key1.dat\n");
    std::filesystem::create_symlink(folder / "key1.dat", folder / "k.png");
    struct Row {
        std::vector<std::string> arguments;
        std::filesystem::path input;
        std::string line;
    };
    const Row rows[] = {
        {{"inbetween", (folder / "key1.dat").string(), (folder / "key2.dat").string(), "--png", (folder / "k.png").string()},
         folder / "key1.dat", (folder / "k.png").string() + ": is an input of this run; --png never writes over an input\n"},
        {{"draw", (folder / "k1").string(), "--svg", (folder / "k1").string()}, folder / "k1",
         (folder / "k1").string() + ": is an input of this run; --svg never writes over an input\n"},
        {{"play", (folder / "scene.scn").string(), "--png", (folder / "k.png").string()}, folder / "key1.dat",
         (folder / "k.png").string() + ": is an input of this run; --png never writes over an input\n"},
    };
    for (const Row& row : rows) {
        CAPTURE(row.arguments);
        const auto result = run_apcs(row.arguments);
        CHECK(result.status == 1);
        CHECK(result.err == row.line);
        CHECK(apcs::test::read_all(row.input) == key);
    }
}
