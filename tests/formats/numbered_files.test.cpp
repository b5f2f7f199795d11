#include "apcs/formats/dat_file.h"
#include "apcs/formats/numbered_files.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <sys/statvfs.h>

using namespace apcs;
using test::run_apcs;
using test::TempFolder;

TEST_CASE("the bytes of numbered files are estimated from the first and the last", "[formats][files]")
{
    const auto sizes = [](std::size_t index, const ContentSink& sink) {
        sink(std::string(index == 0 ? 10 : 20, 'x'));
        sink(std::string(index == 4 ? 10 : 0, 'y'));
    };
    CHECK(estimated_files_bytes(5, sizes) == 5 * (10 + 30) / 2);
    CHECK(estimated_files_bytes(0, sizes) == 0);
}

TEST_CASE("files that do not fit the folder's free space are refused in one line: needed, free", "[formats][files]")
{
    CHECK(room_for_files(1000, 1000, 3, "out", "the frame files"));
    const Expected<void> refused = room_for_files(std::uintmax_t{52} << 30, std::uintmax_t{3} << 30, 100000, "out",
                                                  "the frame files");
    REQUIRE_FALSE(refused);
    CHECK(refused.error().to_string() ==
          "out: the frame files need about 52 GiB (100000 files); the folder has 3 GiB free");
}

TEST_CASE("every target of numbered files is checked before the first is written", "[formats][files]")
{
    // Issue 33: fit with inb002.dat a folder wrote inb001.dat and inb003.dat before failing.
    const TempFolder folder;
    std::filesystem::create_directory(folder / "inb002.dat");
    const KeyFileGuard nothing_read;
    const auto written = write_numbered_files(
        folder.path(), 3, [](std::size_t index) { return "inb00" + std::to_string(index + 1) + ".dat"; },
        [](std::size_t) { return std::string("0 0 0\n"); }, nothing_read, "the in-between files");
    REQUIRE_FALSE(written);
    CHECK(written.error().message == "is a directory; cannot write a file there");
    CHECK_FALSE(std::filesystem::exists(folder / "inb001.dat"));
    CHECK_FALSE(std::filesystem::exists(folder / "inb003.dat"));
}

TEST_CASE("play --out of frames the disk cannot hold is refused before the first file is written",
          "[formats][files][play]")
{
    // Issue 33: a 10^6-point SHAPE over 100000 frames wrote 50 GB in two minutes. Here a SHAPE of
    // as many points as make twice the folder's free space over 100000 frames (a frame's point is
    // 7 bytes or more: "999 1 2").
    const TempFolder folder;
    struct statvfs space {};
    REQUIRE(::statvfs(folder.path().c_str(), &space) == 0);
    const long double free_bytes = static_cast<long double>(space.f_bavail) * space.f_frsize;
    const auto points = static_cast<std::size_t>(2 * free_bytes / (100001.0L * 7)) + 1;
    if (points > max_dat_points) {
        WARN("the temporary folder has more free space than the largest scene needs: not checked");
        return;
    }
    std::string shape;
    shape.reserve(points * 8);
    for (std::size_t point = 0; point < points; ++point)
        shape += std::to_string(point % 1000) + " 1 2\n";
    folder.write("big.dat", shape);
    folder.write("big.scn", "FRAMES 100000\nOBJECT big\nSHAPE big.dat\n");
    std::filesystem::create_directory(folder / "out");

    const auto run = run_apcs({"play", (folder / "big.scn").string(), "--out", (folder / "out").string()});

    CAPTURE(run.err);
    CHECK(run.status == 1);
    CHECK(run.err.starts_with((folder / "out").string() + ": the frame files need about "));
    CHECK(run.err.find(" (100001 files); the folder has ") != std::string::npos);
    CHECK(std::filesystem::is_empty(folder / "out"));
}
