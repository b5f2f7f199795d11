#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

using namespace apcs;
using test::run_apcs;
using test::TempFolder;

namespace {

// A scene of one object `object` whose drawing is one part named `part`, over frames 0 ... last.
void write_named_scene(const TempFolder& folder, const std::string& object, const std::string& part, int last)
{
    folder.write("s.dat", "PART " + part + "\n0 0 0\n1 1 1\n");
    folder.write("a.scn", "FRAMES " + std::to_string(last) + "\nOBJECT " + object + "\nSHAPE s.dat\n");
}

// apcs play a.scn --out out in `folder`.
test::CommandRun play_out(const TempFolder& folder)
{
    return run_apcs({"play", (folder / "a.scn").string(), "--out", (folder / "out").string()});
}

} // namespace

TEST_CASE("play --out refuses a PART line longer than a .dat line before any frame is written",
          "[cli][play][numbered]")
{
    // Issue 45 item 7: OBJECT of 3000 bytes and PART of 1200, each within its own file's line,
    // made "PART OBJECT/PART OPEN" of 4211 bytes: frames that apcs draw could not read back.
    const TempFolder folder;
    write_named_scene(folder, std::string(3000, 'o'), std::string(1200, 'p'), 2);

    const auto run = play_out(folder);

    CAPTURE(run.err);
    CHECK(run.status == 1);
    CHECK(run.err.starts_with((folder / "a.scn").string() + ":2: object 'oooooooooooooooooooooooo...': its part 1 "
                                                             "would be written to the frame files as the line "
                                                             "'PART ooooooooooooooooooo...' of 4211 bytes; "
                                                             "expected at most 4096"));
    CHECK_FALSE(std::filesystem::exists(folder / "out" / "frm000.dat"));
}

TEST_CASE("play --out writes a PART line of exactly 4096 bytes, and it reads back", "[cli][play][numbered]")
{
    // "PART " + 3000 + "/" + 1085 + " OPEN" = 4096 bytes.
    const TempFolder folder;
    write_named_scene(folder, std::string(3000, 'o'), std::string(1085, 'p'), 2);

    const auto run = play_out(folder);

    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const auto drawn = run_apcs({"draw", (folder / "out" / "frm002.dat").string(), "--svg", (folder / "f.svg").string()});
    CAPTURE(drawn.err);
    CHECK(drawn.status == 0);
}

TEST_CASE("play --out names the frames an earlier, longer run left in its folder", "[cli][play][numbered]")
{
    // Issue 45 item 7: frm011.dat ... frm030.dat of a 31-frame run stayed beside a 11-frame run's
    // without a word.
    const TempFolder folder;
    write_named_scene(folder, "a", "p", 30);
    REQUIRE(play_out(folder).status == 0);
    write_named_scene(folder, "a", "p", 10);

    const auto run = play_out(folder);

    CHECK(run.status == 0);
    CHECK(run.err == "apcs: " + (folder / "out" / "frm011.dat").string() + " to " +
                         (folder / "out" / "frm030.dat").string() + " (20 files) are from an earlier run (not rewritten)\n");
    CHECK(std::filesystem::exists(folder / "out" / "frm030.dat")); // the user's to delete: never deleted
    // A run that rewrites the whole set says nothing.
    write_named_scene(folder, "a", "p", 30);
    CHECK(play_out(folder).err.empty());
}

TEST_CASE("play --out names the frames of an earlier run numbered at another width", "[cli][play][numbered]")
{
    // Issue 45 item 7: frm000.dat ... of a short run beside frm0000.dat ... of a long one (and the
    // other way round) made one folder of two sets of frames, said nowhere.
    const TempFolder folder;
    write_named_scene(folder, "a", "p", 1000);
    REQUIRE(play_out(folder).status == 0);
    write_named_scene(folder, "a", "p", 10);

    const auto shorter = play_out(folder);

    CHECK(shorter.status == 0);
    CHECK(shorter.err == "apcs: " + (folder / "out" / "frm0000.dat").string() + " to " +
                             (folder / "out" / "frm1000.dat").string() +
                             " (1001 files) are from an earlier run (not rewritten)\n");
    for (const auto& entry : std::filesystem::directory_iterator(folder / "out"))
        if (entry.path().filename().string().size() == std::string("frm0000.dat").size())
            std::filesystem::remove(entry.path());
    write_named_scene(folder, "a", "p", 1000);

    const auto longer = play_out(folder);

    CHECK(longer.status == 0);
    CHECK(longer.err == "apcs: " + (folder / "out" / "frm000.dat").string() + " to " +
                            (folder / "out" / "frm010.dat").string() +
                            " (11 files) are from an earlier run (not rewritten)\n");
}
