#include "apcs/cli/data_folder.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace apcs;

namespace {

// An installed copy in /usr/local, built in /home/a/build from /home/a/apcs.
DataFolderClues installed_clues()
{
    return {"", "/usr/local/bin/apcs", "/home/a/build", "/home/a/apcs/data"};
}

DataFolderClues build_tree_clues()
{
    return {"", "/home/a/build/apcs", "/home/a/build", "/home/a/apcs/data"};
}

std::string chosen(const DataFolderClues& clues, const std::set<std::string>& folders)
{
    const Expected<std::filesystem::path> folder =
        choose_data_folder(clues, [&](const std::filesystem::path& path) { return folders.count(path.string()) > 0; });
    return folder ? folder->string() : "error: " + folder.error().to_string();
}

} // namespace

TEST_CASE("the data folder is APCS_DATA, else PREFIX/share/apcs, else the source tree's data/ from the build folder",
          "[cli][install]")
{
    const std::set<std::string> everything{"/mine", "/usr/local/share/apcs", "/home/a/share/apcs", "/home/a/apcs/data"};
    DataFolderClues with_environment = installed_clues();
    with_environment.environment = "/mine";
    CHECK(chosen(with_environment, everything) == "/mine");
    CHECK(chosen(installed_clues(), everything) == "/usr/local/share/apcs");
    CHECK(chosen(build_tree_clues(), everything) == "/home/a/share/apcs");
    CHECK(chosen(build_tree_clues(), {"/home/a/apcs/data"}) == "/home/a/apcs/data");
    DataFolderClues tests_binary = build_tree_clues();
    tests_binary.executable = "/home/a/build/tests/apcs_tests";
    CHECK(chosen(tests_binary, {"/home/a/apcs/data"}) == "/home/a/apcs/data");
}

TEST_CASE("an installed program never reads the source tree it was built from", "[cli][install]")
{
    const std::string result = chosen(installed_clues(), {"/home/a/apcs/data"});
    CHECK(result.rfind("error: apcs: the examples are not installed (looked in /usr/local/share/apcs)", 0) == 0);
    CHECK(result.find("set APCS_DATA") != std::string::npos);
    DataFolderClues beside_build = installed_clues();
    beside_build.executable = "/home/a/build-other/apcs";
    CHECK(chosen(beside_build, {"/home/a/apcs/data"}).rfind("error: ", 0) == 0);
}

TEST_CASE("an APCS_DATA that is no folder is said, not passed over", "[cli][install]")
{
    DataFolderClues clues = installed_clues();
    clues.environment = "/nowhere";
    CHECK(chosen(clues, {"/usr/local/share/apcs"}) ==
          "error: APCS_DATA: /nowhere is not a folder; expected the folder that holds the examples n-to-l/, stick/, "
          "snake-apple/ and robot/");
}

TEST_CASE("without its own path the program looks only where APCS_DATA says", "[cli][install]")
{
    const DataFolderClues unknown{"", "", "/home/a/build", "/home/a/apcs/data"};
    CHECK(chosen(unknown, {"/home/a/apcs/data", "/share/apcs"}).rfind("error: apcs: the examples are not installed (looked in no folder)", 0) == 0);
}
