#include "apcs/formats/input_check.h"
#include "apcs/formats/key_script.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <sys/stat.h>

using namespace apcs;

namespace {

// way1.dat as data/exercises ships it; its CRC-32 is what gzip's trailer holds for it.
const std::filesystem::path shipped_way = std::filesystem::path(APCS_SOURCE_DIR) / "data" / "exercises" / "way1.dat";
constexpr std::uint32_t shipped_way_crc32 = 0x1db7d833;

} // namespace

TEST_CASE("an INPUT line names a file of the work folder and its CRC-32 and reads back as written",
          "[formats][exercises][inputs]")
{
    const Expected<ScriptInput> input = parse_input_line("way1.dat crc32 1DB7D833 ; the path", "e.keys", 4);
    REQUIRE(input);
    REQUIRE(input->name == "way1.dat");
    REQUIRE(input->crc32 == shipped_way_crc32);
    REQUIRE(input->line_number == 4);
    REQUIRE(input_line(*input) == "INPUT way1.dat CRC32 1db7d833");
    REQUIRE(input_line({"key1.dat", 0x2a, 1}) == "INPUT key1.dat CRC32 0000002a");
}

TEST_CASE("a malformed INPUT line is refused with its FILE:LINE and what was expected", "[formats][exercises][inputs]")
{
    const auto [line, reason] = GENERATE(table<std::string, std::string>({
        {"INPUT way1.dat 1db7d833", "a file's name, then the word CRC32 and its checksum or nothing"},
        {"INPUT way1.dat CRC32", "a file's name, then the word CRC32 and its checksum or nothing"},
        {"INPUT way1.dat MD5 1db7d833", "a file's name, then the word CRC32 and its checksum or nothing"},
        {"INPUT way1.dat CRC32 1db7d833 extra", "a file's name, then the word CRC32 and its checksum or nothing"},
        {"INPUT ../way1.dat", "NAME a file of the work folder, without a folder"},
        {"INPUT ../way1.dat CRC32 1db7d833", "NAME a file of the work folder, without a folder"},
        {"INPUT .. CRC32 1db7d833", "NAME a file of the work folder, without a folder"},
        {"INPUT way1.dat CRC32 1db7d83g", "XXXXXXXX the CRC-32 of the file's bytes in 8 hex digits"},
        {"INPUT way1.dat CRC32 1db7d83", "XXXXXXXX the CRC-32 of the file's bytes in 8 hex digits"},
        {"INPUT way1.dat CRC32 01db7d833", "XXXXXXXX the CRC-32 of the file's bytes in 8 hex digits"},
        {"INPUT way1.dat CRC32 -1db7d83", "XXXXXXXX the CRC-32 of the file's bytes in 8 hex digits"},
        {"INPUT way1.dat CRC32 0x1db7d8", "XXXXXXXX the CRC-32 of the file's bytes in 8 hex digits"},
    }));
    const Expected<KeyScript> script = parse_captioned_key_script("ENTER\n" + line + "\nSTART\n", "e.keys");
    REQUIRE_FALSE(script);
    REQUIRE(script.error().to_string() == "e.keys:2: expected INPUT NAME [CRC32 XXXXXXXX] (" + reason + "); found '" +
                                              line + "'");
}

TEST_CASE("INPUT lines stand in the preamble before START and name each file once", "[formats][exercises][inputs]")
{
    const Expected<KeyScript> script =
        parse_captioned_key_script("INPUT key1.dat CRC32 de215594\nENTER\nINPUT way1.dat CRC32 1db7d833\nSTART\n4\n",
                                   "e.keys");
    REQUIRE(script);
    REQUIRE(script->inputs.size() == 2);
    REQUIRE(script->inputs[1] == ScriptInput{"way1.dat", shipped_way_crc32, 3});
    REQUIRE(script->events.size() == 2);
    const auto [text, message] = GENERATE(table<std::string, std::string>({
        {"START\nINPUT way1.dat CRC32 1db7d833\n",
         "e.keys:2: INPUT after START, a caption or GOAL; expected an exercise's INPUT lines in its preamble, before "
         "START (they are checked before the replay begins)"},
        {";; a caption\nINPUT way1.dat CRC32 1db7d833\n",
         "e.keys:2: INPUT after START, a caption or GOAL; expected an exercise's INPUT lines in its preamble, before "
         "START (they are checked before the replay begins)"},
        {"INPUT way1.dat CRC32 1db7d833\nINPUT WAY1.DAT CRC32 1db7d833\n",
         "e.keys:2: a second INPUT WAY1.DAT (the first is on line 1); expected each input named once"},
    }));
    const Expected<KeyScript> refused = parse_captioned_key_script(text, "e.keys");
    REQUIRE_FALSE(refused);
    REQUIRE(refused.error().to_string() == message);
}

TEST_CASE("the CRC-32 of a shipped input is zlib's as gzip's trailer holds it", "[formats][exercises][inputs]")
{
    const Expected<std::uint32_t> crc32 = file_crc32(shipped_way);
    REQUIRE(crc32);
    REQUIRE(*crc32 == shipped_way_crc32);
}

TEST_CASE("an input that differs or is missing or a FIFO or a symbolic link is refused with the script's FILE:LINE",
          "[formats][exercises][inputs]")
{
    const test::TempFolder folder;
    std::filesystem::copy_file(shipped_way, folder / "way1.dat");
    const std::vector<ScriptInput> inputs{{"way1.dat", shipped_way_crc32, 7}};
    REQUIRE(check_script_inputs(inputs, folder.path(), "e.keys"));
    const std::string again = ": copy the exercise's files into the work folder again";
    SECTION("a rewritten file")
    {
        folder.write("way1.dat", "3\n0 0 0\n1 1 1\n2 2 2\n");
        const Expected<void> checked = check_script_inputs(inputs, folder.path(), "e.keys");
        REQUIRE_FALSE(checked);
        REQUIRE(checked.error().to_string().starts_with("e.keys:7: way1.dat differs from the exercise's (CRC-32 "));
        REQUIRE(checked.error().to_string().ends_with(", expected 1db7d833): a session rewrote it, or it is another "
                                                      "exercise's; copy the exercise's files into the work folder again"));
    }
    SECTION("a missing file")
    {
        std::filesystem::remove(folder / "way1.dat");
        const Expected<void> checked = check_script_inputs(inputs, folder.path(), "e.keys");
        REQUIRE_FALSE(checked);
        REQUIRE(checked.error().to_string() == "e.keys:7: way1.dat is missing from the work folder " +
                                                   folder.path().string() + "; expected the exercise's input" + again);
    }
    SECTION("a FIFO, which is never opened")
    {
        std::filesystem::remove(folder / "way1.dat");
        REQUIRE(::mkfifo((folder / "way1.dat").c_str(), 0600) == 0);
        const Expected<void> checked = check_script_inputs(inputs, folder.path(), "e.keys");
        REQUIRE_FALSE(checked);
        REQUIRE(checked.error().to_string() ==
                "e.keys:7: way1.dat is a FIFO; expected the exercise's input, a regular file of its own" + again);
    }
    SECTION("a symbolic link, even to the right content")
    {
        std::filesystem::rename(folder / "way1.dat", folder / "kept.dat");
        std::filesystem::create_symlink("kept.dat", folder / "way1.dat");
        const Expected<void> checked = check_script_inputs(inputs, folder.path(), "e.keys");
        REQUIRE_FALSE(checked);
        REQUIRE(checked.error().to_string() ==
                "e.keys:7: way1.dat is a symbolic link; expected the exercise's input, a regular file of its own" +
                    again);
    }
}

TEST_CASE("A script of more keys than the reader takes is refused at the line that passes the most, keys or TEXT",
          "[formats][issue57]")
{
    REQUIRE(parse_captioned_key_script("6 6\n6\n", "s.keys", 3));
    const auto tokens = parse_captioned_key_script("6 6\n; a comment\n6 6\n6\n", "s.keys", 3);
    REQUIRE(!tokens);
    REQUIRE(tokens.error().to_string() == "s.keys:3: too long: more than 3 keys, at most 3 are read");
    const auto typed = parse_captioned_key_script("6\nTEXT way1.dat\n", "s.keys", 3);
    REQUIRE(!typed);
    REQUIRE(typed.error().to_string() == "s.keys:2: too long: more than 3 keys, at most 3 are read");
}
