#include "apcs/formats/file_io.h"
#include "apcs/formats/unfinished_files.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

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

namespace {

// The hidden files (".NAME.XXXXXX", a temporary file) in `folder`.
std::vector<std::string> hidden_files(const std::filesystem::path& folder)
{
    std::vector<std::string> hidden;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().filename().string().starts_with('.'))
            hidden.push_back(entry.path().filename().string());
    return hidden;
}

} // namespace

TEST_CASE("a folder renamed while a file is written in it keeps no temporary file: the file is put in place there",
          "[formats][files][signals]")
{
    // Issue 45 item 7: play --out into DIR, `mv DIR DIR2` meanwhile, left two .frmNNN.dat.XXXXXX in
    // DIR2: the rename and the removal both named DIR/.frmNNN.dat.XXXXXX, which was gone.
    const TempFolder folder;
    std::filesystem::create_directory(folder / "out");
    const Expected<WriteResult> written =
        write_file_atomically(folder / "out" / "frm001.dat", [&folder](const ContentSink& sink) {
            sink("0 0 0\n");
            std::filesystem::rename(folder / "out", folder / "moved");
            sink("1 1 1\n");
        });

    CHECK(written.has_value());
    CHECK(hidden_files(folder / "moved").empty());
    CHECK(test::read_all(folder / "moved" / "frm001.dat") == "0 0 0\n1 1 1\n");
}

TEST_CASE("a write that fails after its folder was renamed removes its temporary file there",
          "[formats][files][signals]")
{
    const TempFolder folder;
    std::filesystem::create_directory(folder / "out");
    const Expected<WriteResult> written =
        write_file_atomically(folder / "out" / "frm001.dat", [&folder](const ContentSink& sink) {
            sink("0 0 0\n");
            std::filesystem::rename(folder / "out", folder / "moved");
            // The rename over frm001.dat will fail: a folder has taken its name.
            std::filesystem::create_directory(folder / "moved" / "frm001.dat");
            sink("1 1 1\n");
        });

    REQUIRE_FALSE(written.has_value());
    CHECK(written.error().message.starts_with("cannot replace the file: "));
    CHECK(hidden_files(folder / "moved").empty());
}

TEST_CASE("a stop removes a temporary file whose folder was renamed meanwhile", "[formats][files][signals]")
{
    const TempFolder folder;
    std::filesystem::create_directory(folder / "out");
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        [[maybe_unused]] const Expected<WriteResult> written =
            write_file_atomically(folder / "out" / "frm001.dat", [&folder](const ContentSink& sink) {
                sink("0 0 0\n");
                std::filesystem::rename(folder / "out", folder / "moved");
                remove_unfinished_files(); // what the signal handler does, before its _exit
                ::_exit(hidden_files(folder / "moved").empty() ? 0 : 1);
            });
        ::_exit(2);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}

TEST_CASE("a stop removes the unfinished folder with the files and folders it holds, and a folder made after "
          "the stop begins is refused",
          "[formats][files][signals]")
{
    // apcs grade's private folder under TMPDIR (its copies, a work folder a session writes in) was
    // left behind by SIGTERM: /tmp/apcs-grade-p328MP/work/ani4.dat ...
    const TempFolder folder;
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        const int parent = ::open(folder.path().c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
        std::string name = "apcs-grade-XXXXXX";
        std::optional<UnfinishedFolder> known;
        if (parent < 0 || create_unfinished_folder(parent, name, known) != 0 || name == "apcs-grade-XXXXXX")
            ::_exit(2);
        const std::filesystem::path made = folder / name;
        const auto write = [](const std::filesystem::path& file, const char* text) { std::ofstream(file) << text; };
        std::filesystem::create_directories(made / "work" / "deeper");
        for (int file = 0; file < 300; ++file) // more than one read of the folder holds
            write(made / "work" / ("ani" + std::to_string(file) + ".dat"), "0 0 0\n");
        write(made / "work" / "deeper" / "apcs.log", "session started\n");
        write(made / "key1.dat", "0 0 0\n");
        remove_unfinished_files(); // what the signal handler does, before its _exit
        std::string late = "late-XXXXXX";
        std::optional<UnfinishedFolder> refused;
        const bool late_refused = create_unfinished_folder(parent, late, refused) != 0 && errno == EINTR;
        ::_exit(std::filesystem::is_empty(folder.path()) && late_refused ? 0 : 1);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}

TEST_CASE("a stop ends even when the unfinished folder holds what it cannot remove", "[formats][files][signals]")
{
    // A folder nested deeper than the stop goes made it spin at 100 % CPU until SIGKILL.
    const TempFolder folder;
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        ::alarm(20); // a stop that spins is killed, and the test fails
        const int parent = ::open(folder.path().c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
        std::string name = "apcs-grade-XXXXXX";
        std::optional<UnfinishedFolder> known;
        if (parent < 0 || create_unfinished_folder(parent, name, known) != 0)
            ::_exit(2);
        std::filesystem::path deep = folder / name;
        for (int level = 0; level < 12; ++level)
            deep /= "d";
        std::filesystem::create_directories(deep);
        std::ofstream(deep / "apcs.log") << "session started\n";
        std::ofstream(folder / name / "key1.dat") << "0 0 0\n";
        remove_unfinished_files();
        // What lies within the depth went; the deepest, left, keeps its folders.
        const bool top_gone = !std::filesystem::exists(folder / name / "key1.dat");
        ::_exit(top_gone && std::filesystem::exists(deep / "apcs.log") ? 0 : 1);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}
