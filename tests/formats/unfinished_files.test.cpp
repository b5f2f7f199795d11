#include "apcs/formats/file_io.h"
#include "apcs/formats/unfinished_files.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

using namespace apcs;
using test::TempFolder;

TEST_CASE("once a stop has begun no temporary file is made, so a writer still running leaves none behind",
          "[formats][files][signals]")
{
    // Issue 33: play --out stopped by SIGTERM left .frm053.dat.kwibJN (2 MiB). The handler removes
    // the temporary files on one thread while the writers go on until _exit; one they made after
    // the removal stayed. The stop runs in a child, since it lasts until the program ends.
    const TempFolder folder;
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        remove_unfinished_files(); // what the signal handler does, before its _exit
        const Expected<WriteResult> written =
            write_file_atomically(folder / "frm053.dat", std::string(std::size_t{1} << 21, 'x'));
        const bool left_nothing = std::filesystem::is_empty(folder.path());
        ::_exit(!written && left_nothing ? 0 : 1);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}
