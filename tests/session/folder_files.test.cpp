#include "apcs/session/session_files.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sys/stat.h>

using namespace apcs;

TEST_CASE("the session log is appended to a regular apcs.log only: never a FIFO, never through a link",
          "[session][files]")
{
    const test::TempFolder root;
    std::filesystem::create_directory(root / "work");
    FolderFiles files(root / "work");
    files.log("first");
    files.log("second");
    CHECK(test::read_all(root / "work" / "apcs.log") == "first\nsecond\n");

    // A FIFO nobody reads: opening it to write would wait forever.
    std::filesystem::remove(root / "work" / "apcs.log");
    REQUIRE(::mkfifo((root / "work" / "apcs.log").c_str(), 0644) == 0);
    files.log("not written");
    CHECK(std::filesystem::is_fifo(root / "work" / "apcs.log"));

    // A link out of the work folder: the file it names stays as it was.
    std::filesystem::remove(root / "work" / "apcs.log");
    root.write("outside.txt", "someone's\n");
    std::filesystem::create_symlink(root / "outside.txt", root / "work" / "apcs.log");
    files.log("not written");
    CHECK(test::read_all(root / "outside.txt") == "someone's\n");
}
