#include "support/golden.h"
#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace apcs;

namespace {

// A copy of a bundled example, so that the session's writes do not touch data/.
void copy_example(const std::string& example, const test::TempFolder& folder)
{
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "data" / example))
        std::filesystem::copy_file(entry.path(), folder / entry.path().filename().string());
}

} // namespace

TEST_CASE("the N to L session replays headless to its approved screens and files", "[session][headless]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    const auto result = test::run_apcs({"--keys", (folder / "session.keys").string(), "--workdir",
                                        folder.path().string(), "--glyphs", "ascii"});
    REQUIRE(result.err.empty());
    REQUIRE(result.status == 0);
    test::check_golden("n-to-l/screens.txt", result.out);
    for (const char* name : {"way1.dat", "way4.dat", "inb001.dat", "inb006.dat", "inb012.dat", "ani2.dat"})
        test::check_golden(std::string("n-to-l/") + name, test::read_all(folder / name));
    REQUIRE(std::filesystem::exists(folder / "way1.bak"));
    REQUIRE_FALSE(std::filesystem::exists(folder / "inb013.dat"));
}

TEST_CASE("a recorded session replays to the same files", "[session][headless]")
{
    const test::TempFolder first;
    const test::TempFolder second;
    copy_example("n-to-l", first);
    copy_example("n-to-l", second);
    const auto recorded = test::run_apcs({"--keys", (first / "session.keys").string(), "--workdir",
                                          first.path().string(), "--record", (first / "again.keys").string()});
    REQUIRE(recorded.status == 0);
    const auto replayed = test::run_apcs({"--keys", (first / "again.keys").string(), "--workdir", second.path().string()});
    REQUIRE(replayed.status == 0);
    REQUIRE(replayed.out == recorded.out);
    for (const char* name : {"way1.dat", "way4.dat", "inb007.dat", "apcs.log"})
        REQUIRE(test::read_all(first / name) == test::read_all(second / name));
}

TEST_CASE("without a terminal and without --keys the session refuses with exit 3", "[session][headless]")
{
    const test::TempFolder folder;
    const auto result = test::run_apcs({"--workdir", folder.path().string()});
    REQUIRE(result.status == 3);
    REQUIRE_FALSE(std::filesystem::exists(folder / "apcs.log")); // nothing written when nothing runs
    REQUIRE(result.err == "apcs: standard input is not a terminal; give --keys FILE to replay a session without one\n");
}

TEST_CASE("a bad key script is exit 1 with FILE:LINE", "[session][headless]")
{
    const test::TempFolder folder;
    const auto script = folder.write("bad.keys", "ENTER\nHOME\n");
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    REQUIRE(result.status == 1);
    REQUIRE(result.err.starts_with(script.string() + ":2: expected a single printable character"));
}

TEST_CASE("a script that ends early says at which step", "[session][headless]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    const auto script = folder.write("short.keys", "ENTER\n");
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.err == "apcs: the key script ended at step 1: KEY2 file\n");
}
