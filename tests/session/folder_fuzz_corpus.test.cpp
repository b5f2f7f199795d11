#include "fuzz/hostile_folder.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <unistd.h>

using namespace apcs;

namespace {

// Each run flushes every file it writes: in memory, where there is such a folder, the corpus
// replays in seconds even when the disk is busy.
std::filesystem::path run_base()
{
    std::error_code error;
    const std::filesystem::path memory = "/dev/shm";
    return std::filesystem::is_directory(memory, error) && ::access(memory.c_str(), W_OK) == 0
               ? memory
               : std::filesystem::temp_directory_path();
}

} // namespace

TEST_CASE("every input of the folder session fuzzing corpus leaves special, read-only, key and outside files as they were",
          "[session][fuzz]")
{
    std::size_t inputs = 0;
    std::size_t reached_fitting = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) /
                                                                 "tests/fuzz/folder_session")) {
        const std::string bytes = test::read_all(entry.path());
        const fuzzing::FolderRun run = fuzzing::play_in_hostile_folder(
            {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, run_base());
        ++inputs;
        INFO(entry.path().filename().string());
        REQUIRE(run.violation.value_or("") == "");
        if (std::find(run.written.begin(), run.written.end(), "inb001.dat") != run.written.end())
            ++reached_fitting;
    }
    REQUIRE(inputs > 20);
    // The corpus reaches the in-betweens, not only the first prompts.
    REQUIRE(reached_fitting > 0);
}

TEST_CASE("the folder fuzzer's invariants catch a special file replaced, a key file written and a temporary file left",
          "[session][fuzz]")
{
    const test::TempFolder root;
    std::filesystem::create_directories(root / "work");
    std::filesystem::create_directories(root / "outside");
    fuzzing::hostile::populate(root / "work", root / "outside");
    const fuzzing::FolderState work = fuzzing::snapshot(root / "work");
    const fuzzing::FolderState outside = fuzzing::snapshot(root / "outside");
    const std::vector<fuzzing::FileIdentity> keys{*fuzzing::hostile::identity_of(root / "work/key1.dat")};
    REQUIRE_FALSE(fuzzing::hostile::check_invariants(root.path(), work, outside, keys));

    SECTION("a FIFO replaced by a regular file")
    {
        std::filesystem::remove(root / "work/fifo.dat");
        root.write("work/fifo.dat", "0 0 0\n");
    }
    SECTION("a key file written under its hard link") { root.write("work/keyhard.dat", "1 2 3\n"); }
    SECTION("a file outside the folder written") { root.write("outside/victim.dat", "1 2 3\n"); }
    SECTION("a temporary file left behind") { root.write("work/.ani1.dat.a1B2c3", ""); }
    SECTION("a read-only file replaced by a writable one")
    {
        std::filesystem::remove(root / "work/readonly.dat");
        root.write("work/readonly.dat", "0 0 0\n3 -4 5\n0 0 10\n");
    }
    REQUIRE(fuzzing::hostile::check_invariants(root.path(), work, outside, keys));
}

TEST_CASE("the folder fuzzer's invariants let a link to a file that is no key be written through", "[session][fuzz]")
{
    const test::TempFolder root;
    std::filesystem::create_directories(root / "work");
    std::filesystem::create_directories(root / "outside");
    fuzzing::hostile::populate(root / "work", root / "outside");
    const fuzzing::FolderState work = fuzzing::snapshot(root / "work");
    const fuzzing::FolderState outside = fuzzing::snapshot(root / "outside");
    root.write("work/keylink.dat", "1 2 3\n4 5 6\n");
    REQUIRE_FALSE(fuzzing::hostile::check_invariants(root.path(), work, outside, {}));
}

// Inputs on which the folder fuzzer found a file replaced that must stay: a .bak that is a FIFO, a
// link or read-only (all four failed before write_file_atomically checked the backup's type).
TEST_CASE("the folder fuzzer's findings leave special and read-only files as they were", "[session][fuzz][finding]")
{
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) /
                                                                 "tests/fuzz/folder_session_findings")) {
        const std::string bytes = test::read_all(entry.path());
        INFO(entry.path().filename().string());
        CHECK(fuzzing::play_in_hostile_folder({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()})
                  .violation.value_or("") == "");
    }
}

namespace {

std::string with_choices(std::string bytes, unsigned char first, unsigned char second)
{
    bytes[0] = static_cast<char>(first);
    bytes[1] = static_cast<char>(second);
    return bytes;
}

fuzzing::FolderRun play(const std::string& bytes)
{
    return fuzzing::play_in_hostile_folder({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()},
                                           run_base());
}

long inbetweens_written(const fuzzing::FolderRun& run)
{
    return std::count_if(run.written.begin(), run.written.end(),
                         [](const std::string& name) { return name.starts_with("inb"); });
}

} // namespace

TEST_CASE("an earlier run's in-between files are replaced as a whole set or not at all, whatever stands in the way",
          "[session][fuzz]")
{
    // Choices 6 and 7 put FIFOs where the session writes pictures and way1.bak, which a session
    // that fits does not touch: a corpus input that writes its in-between files beside them is
    // replayed over each earlier run (choices 252-255) and over a read-only inb003.dat (4 x 9 + 5).
    std::optional<std::string> reaching;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) /
                                                                 "tests/fuzz/folder_session")) {
        const std::string bytes = test::read_all(entry.path());
        if (bytes.size() > 2 && inbetweens_written(play(with_choices(bytes, 6, 7))) >= 3) {
            reaching = bytes;
            break;
        }
    }
    REQUIRE(reaching);
    const auto written_with = [&](unsigned char first, unsigned char second) {
        const fuzzing::FolderRun run = play(with_choices(*reaching, first, second));
        INFO("choices " << int{first} << " " << int{second});
        REQUIRE(run.violation.value_or("") == "");
        return inbetweens_written(run);
    };
    CHECK(written_with(252, 7) >= 3); // an earlier inb002.dat is replaced with the rest
    CHECK(written_with(254, 255) >= 3);
    CHECK(written_with(252, 253) == 0); // inb002.dat's old content has nowhere to go: none written
    CHECK(written_with(41, 252) == 0);  // inb003.dat read-only: none written, inb002.dat as it was
}
