#include "apcs/formats/dat_file.h"
#include "apcs/formats/numbered_files.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <filesystem>
#include <string>
#include <sys/statvfs.h>
#include <unistd.h>

using namespace apcs;
using test::run_apcs;
using test::TempFolder;

TEST_CASE("the bytes of numbered files are measured file by file when small, else estimated from five spread over the run",
          "[formats][files]")
{
    const auto sizes = [](std::size_t index, const ContentSink& sink) {
        sink(std::string(index == 0 ? 10 : 20, 'x'));
        sink(std::string(index == 4 ? 10 : 0, 'y'));
    };
    CHECK(estimated_files_bytes(5, sizes) == 10 + 20 + 20 + 20 + 30);
    CHECK(estimated_files_bytes(0, sizes) == 0);
    // Issue 45: ends of 10 bytes, 99 middle files of 100 (a move's middle frames have more
    // digits): the files 0, 25, 50, 75, 100 alone would say 6464 of the 9920 bytes; a run this
    // small is measured whole.
    const auto middles = [](std::size_t index, const ContentSink& sink) {
        sink(std::string(index == 0 || index == 100 ? 10 : 100, 'x'));
    };
    CHECK(estimated_files_bytes(101, middles) == 9920);
    CHECK(estimated_files_bytes(1, middles) == 10);
    // Five samples saying 8 MiB or more stand for the run: 10 + 3 x 204800 + 10 over 5, 101 times.
    const auto large_middles = [](std::size_t index, const ContentSink& sink) {
        sink(std::string(index == 0 || index == 100 ? 10 : 204800, 'x'));
    };
    CHECK(estimated_files_bytes(101, large_middles) == 12411284);
    // Each file takes whole blocks: the session's 12 small files took 48 KiB, not 2.1 KiB.
    const auto small = [](std::size_t, const ContentSink& sink) { sink(std::string(180, 'x')); };
    CHECK(estimated_files_bytes(12, small) == 12 * 180);
    CHECK(estimated_files_bytes(12, small, 4096) == 12 * 4096);
    CHECK(estimated_files_bytes(2, [](std::size_t, const ContentSink& sink) { sink(std::string(4097, 'x')); }, 4096) ==
          2 * 8192);
}

TEST_CASE("where the room is ample the free-space check makes one file of the run and not five", "[formats][files]")
{
    // Issue 44 item 7: five samples made before the first write cost the fit of 10^5 points x 12
    // in-betweens 5 of its 12 frames again. Now the middle file alone, when the run would take a
    // quarter of the free space or less by it.
    const TempFolder folder;
    std::atomic<int> made = 0;
    const auto writer_of = [&made](std::size_t, const ContentSink& sink) {
        ++made;
        sink("0 0 0\n");
    };
    const auto written = write_numbered_files(
        folder.path(), 12, [](std::size_t index) { return "inb" + std::to_string(100 + index + 1) + ".dat"; },
        writer_of, KeyFileGuard{}, "the in-between files");
    REQUIRE(written);
    CHECK(written->size() == 12);
    CHECK(made == 12 + 1);
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

TEST_CASE("a read-only target or a backup that cannot be kept stops numbered files before the first is written",
          "[formats][files]")
{
    // Issue 45: a read-only frm010.dat, or inb003.bak a folder, had let the files before it be
    // replaced: a folder of two runs.
    const TempFolder folder;
    const auto name_of = [](std::size_t index) { return "inb00" + std::to_string(index + 1) + ".dat"; };
    for (std::size_t index = 0; index < 3; ++index)
        REQUIRE(write_file_atomically(folder / name_of(index), "old\n"));
    const auto new_content = [](std::size_t) { return std::string("new\n"); };
    const auto old_everywhere = [&] {
        for (std::size_t index = 0; index < 3; ++index)
            if (test::read_all(folder / name_of(index)) != "old\n")
                return false;
        return true;
    };
    SECTION("a read-only file whose content would change")
    {
        std::filesystem::permissions(folder / "inb003.dat", std::filesystem::perms::owner_read);
        const auto written = write_numbered_files(folder.path(), 3, name_of, new_content, KeyFileGuard{}, "the in-between files");
        REQUIRE_FALSE(written);
        CHECK(written.error().message == "is read-only (mode 0400); not replaced");
        CHECK(old_everywhere());
        // The same content over it is no change, and the run goes on.
        const auto same = write_numbered_files(folder.path(), 3, name_of, [](std::size_t) { return std::string("old\n"); },
                                               KeyFileGuard{}, "the in-between files");
        CHECK(same);
    }
    SECTION("a backup that is a folder")
    {
        std::filesystem::create_directory(folder / "inb002.bak");
        const auto written = write_numbered_files(folder.path(), 3, name_of, new_content, KeyFileGuard{}, "the in-between files");
        REQUIRE_FALSE(written);
        CHECK(written.error().message ==
              "cannot keep the old file as " + (folder / "inb002.bak").string() +
                  ": it is a directory; a backup replaces only a regular file");
        CHECK(old_everywhere());
    }
}

TEST_CASE("numbered files the folder cannot hold are refused before the first is written, whatever the disk",
          "[formats][files]")
{
    // Two files of 128 TiB each, counted chunk by chunk (a 64 MiB chunk sent 2^21 times), nothing
    // kept: more than any disk the tests run on has free.
    const TempFolder folder;
    const std::string chunk(std::size_t{1} << 26, 'x');
    const auto huge = [&chunk](std::size_t, const ContentSink& sink) {
        for (int piece = 0; piece < (1 << 21) && sink(chunk); ++piece) {
        }
    };
    const auto written = write_numbered_files(
        folder.path(), 2, [](std::size_t index) { return "frm" + std::to_string(index) + ".dat"; }, huge,
        KeyFileGuard{}, "the frame files");
    REQUIRE_FALSE(written);
    CHECK(written.error().message.starts_with("the frame files need about 256 TiB (2 files); the folder has "));
    CHECK(std::filesystem::is_empty(folder.path()));
}

TEST_CASE("play --out of frames the disk cannot hold is refused before the first file is written",
          "[formats][files][play]")
{
    // Issue 33: a 10^6-point SHAPE over 100000 frames wrote 50 GB in two minutes. Here a SHAPE of
    // as many points as make twice the folder's free space over 100000 frames (a frame's point is
    // 7 bytes or more: "999 1 2"), in whichever of the temporary folder and /dev/shm (a tmpfs of
    // half the memory) has less: the largest scene (10^6 points) outgrows up to 350 GB.
    const auto free_bytes_in = [](const std::filesystem::path& folder) {
        struct statvfs space {};
        return ::statvfs(folder.c_str(), &space) == 0 ? static_cast<long double>(space.f_bavail) * space.f_frsize
                                                       : -1.0L;
    };
    std::filesystem::path base = std::filesystem::temp_directory_path();
    const long double in_shm = free_bytes_in("/dev/shm");
    if (in_shm > 0 && in_shm < free_bytes_in(base) && ::access("/dev/shm", W_OK) == 0)
        base = "/dev/shm";
    const TempFolder folder(base);
    const long double free_bytes = free_bytes_in(folder.path());
    const auto points = static_cast<std::size_t>(2 * free_bytes / (100001.0L * 7)) + 1;
    INFO(base.string() << " has " << free_bytes << " bytes free: a scene that outgrows it needs " << points
                       << " points, and a SHAPE holds at most " << max_dat_points);
    REQUIRE(points <= max_dat_points);
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
