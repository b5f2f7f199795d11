#include "apcs/formats/file_io.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

using namespace apcs;
using test::read_all;
using test::TempFolder;

TEST_CASE("a missing name finds the file that differs only in case", "[formats][files]")
{
    const TempFolder folder;
    folder.write("key1.dat", "0 0\n1 1\n");
    REQUIRE(resolve_input_path(folder / "KEY1.DAT") == folder / "key1.dat");
    const Expected<DatFile> file = read_dat_file(folder / "KEY1.DAT");
    REQUIRE(file.has_value());
    REQUIRE(file->point_count() == 2);
}

TEST_CASE("reading a missing file or a folder names the file", "[formats][files]")
{
    const TempFolder folder;
    const std::string missing = (folder / "none.dat").string();
    REQUIRE(read_dat_file(missing).error().to_string() == missing + ": cannot open: No such file or directory");
    REQUIRE(read_dat_file(folder.path()).error().to_string() == folder.path().string() + ": is a directory; expected a file");
}

TEST_CASE("an atomic write creates, keeps identical files untouched and backs up changed ones", "[formats][files]")
{
    const TempFolder folder;
    const auto target = folder / "way1.dat";
    Expected<WriteResult> first = write_file_atomically(target, "0 0 0\n1 1 1\n");
    REQUIRE(first.has_value());
    REQUIRE(first->outcome == WriteOutcome::created);
    REQUIRE(read_all(target) == "0 0 0\n1 1 1\n");
    REQUIRE_FALSE(std::filesystem::exists(folder / "way1.bak"));

    REQUIRE(write_file_atomically(target, "0 0 0\n1 1 1\n")->outcome == WriteOutcome::unchanged);
    REQUIRE_FALSE(std::filesystem::exists(folder / "way1.bak"));

    const Expected<WriteResult> changed = write_file_atomically(target, "0 0 0\n2 2 2\n");
    REQUIRE(changed->outcome == WriteOutcome::replaced);
    REQUIRE(changed->backup == folder / "way1.bak");
    REQUIRE(read_all(target) == "0 0 0\n2 2 2\n");
    REQUIRE(read_all(folder / "way1.bak") == "0 0 0\n1 1 1\n");

    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder.path()))
        ++entries;
    REQUIRE(entries == 2); // no temporary file left behind
}

TEST_CASE("a failed write reports why and leaves no file", "[formats][files]")
{
    const TempFolder folder;
    const Expected<WriteResult> into_missing = write_file_atomically(folder / "no/such/way1.dat", "1 1\n");
    REQUIRE_FALSE(into_missing.has_value());
    REQUIRE(into_missing.error().message.starts_with("cannot create a temporary file in"));

    std::filesystem::create_directory(folder / "taken.dat");
    const Expected<WriteResult> over_folder = write_file_atomically(folder / "taken.dat", "1 1\n");
    REQUIRE(over_folder.error().message == "is a directory; cannot write a file there");
    REQUIRE(std::filesystem::is_directory(folder / "taken.dat"));
}

TEST_CASE("the backup of a .bak file is not the file itself", "[formats][files]")
{
    REQUIRE(backup_path_for("a/way1.dat") == "a/way1.bak");
    REQUIRE(backup_path_for("way1.bak") == "way1.bak.bak");
    REQUIRE(backup_path_for("noext") == "noext.bak");
}
