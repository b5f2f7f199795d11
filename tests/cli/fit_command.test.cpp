#include "apcs/cli/command_line.h"
#include "apcs/formats/file_io.h"

#include "support/png_pixels.h"
#include "support/run_apcs.h"
#include "support/small_example.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

using namespace apcs;
using test::run_apcs;
using test::TempFolder;

TEST_CASE("apcs fit --print writes frames 0 to M+1: padded KEY1, the in-betweens, KEY2", "[cli][fit]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const auto result = run_apcs({"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                  (folder / "way1.dat").string(), (folder / "way4.dat").string(), "--inbetweens", "2",
                                  "--samples", "2", "--print"});
    REQUIRE(result.status == 0);
    CHECK(result.err.empty());
    // KEY2 (0,0,10) (0,0,0) (0,5,0) gains (0,0,5) between its first two points (Algorithm 2).
    // way1 with 2 samples per segment: samples at u = 1/2 are (1.875, −2.5, 2.5) and (1.875, −2.5, 7.5),
    // and the 2 in-betweens at L/3, 2L/3 fall nearest to those.
    const std::string expected_start = "# frame 0\n"
                                       "0.000000 0.000000 0.000000\n"
                                       "0.000000 0.000000 10.000000\n"
                                       "0.000000 6.000000 0.000000\n"
                                       "0.000000 6.000000 10.000000\n"
                                       "# frame 1\n"
                                       "1.875000 -2.500000 2.500000\n";
    REQUIRE(result.out.substr(0, expected_start.size()) == expected_start);
    const std::string expected_end = "# frame 3\n"
                                     "0.000000 0.000000 10.000000\n"
                                     "0.000000 0.000000 5.000000\n"
                                     "0.000000 0.000000 0.000000\n"
                                     "0.000000 5.000000 0.000000\n";
    REQUIRE(result.out.ends_with(expected_end));
}

TEST_CASE("apcs fit writes inb001.dat … with the whole graphic and its parts", "[cli][fit]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const auto result = run_apcs({"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                  (folder / "way1.dat").string(), (folder / "way4.dat").string(), "--inbetweens", "3",
                                  "--out", folder.path().string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.out.empty());
    for (const char* name : {"inb001.dat", "inb002.dat", "inb003.dat"}) {
        const Expected<DatFile> frame = read_dat_file(folder / name);
        REQUIRE(frame.has_value());
        REQUIRE(frame->point_count() == 4);
    }
    REQUIRE_FALSE(std::filesystem::exists(folder / "inb004.dat"));
}

TEST_CASE("apcs fit streams the in-betweens it writes alone: the same files as with all frames held", "[cli][fit]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    std::filesystem::create_directory(folder / "streamed");
    std::filesystem::create_directory(folder / "held");
    const std::vector<std::string> inputs{(folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                          (folder / "way1.dat").string(), (folder / "way4.dat").string()};
    const auto run = [&](const std::string& out, bool with_picture) {
        std::vector<std::string> arguments{"fit"};
        arguments.insert(arguments.end(), inputs.begin(), inputs.end());
        for (const std::string extra : {"--inbetweens", "5", "--out", out.c_str()})
            arguments.push_back(extra);
        if (with_picture) { // a picture needs every frame: the frames are held, then written
            arguments.push_back("--png");
            arguments.push_back((folder / "all.png").string());
        }
        return run_apcs(arguments);
    };
    REQUIRE(run((folder / "streamed").string(), false).status == 0);
    REQUIRE(run((folder / "held").string(), true).status == 0);
    for (int k = 1; k <= 5; ++k) {
        const std::string name = "inb00" + std::to_string(k) + ".dat";
        CAPTURE(name);
        REQUIRE(test::read_all(folder / "streamed" / name) == test::read_all(folder / "held" / name));
    }
    // The keys' largest coordinate is 10: 9 - 1 = 8 decimals in every number.
    std::istringstream lines(test::read_all(folder / "streamed" / "inb001.dat"));
    std::string line;
    std::getline(lines, line); // the heading
    int numbers = 0;
    for (std::string field; lines >> field; ++numbers) {
        CAPTURE(field);
        REQUIRE(field.size() - field.find('.') == 9);
    }
    CHECK(numbers == 12);
}

TEST_CASE("a path that does not start at the graphic point is refused with the expected point", "[cli][fit]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    folder.write("bad.dat", "; wrong start\n0 1 0\n0 0 10\n");
    const auto result = run_apcs({"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                  (folder / "bad.dat").string(), (folder / "way4.dat").string(), "--print"});
    REQUIRE(result.status == 1);
    REQUIRE(result.out.empty());
    REQUIRE(result.err == (folder / "bad.dat").string() +
                              ":2: the path starts at (0, 1, 0); expected the first graphic point's KEY1 position (0, 0, 0)\n");
    const auto wrong_end = run_apcs({"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                     (folder / "way1.dat").string(), (folder / "way1.dat").string(), "--print"});
    REQUIRE(wrong_end.status == 1);
    REQUIRE(wrong_end.err.find("expected the last graphic point's KEY1 position (0, 6, 10)") != std::string::npos);
}

TEST_CASE("apcs fit --out makes a missing folder, one level — a missing parent fails and writes nothing", "[cli][fit]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const std::vector<std::string> files{"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                         (folder / "way1.dat").string(), (folder / "way4.dat").string(), "--out"};
    std::vector<std::string> made = files;
    made.push_back((folder / "frames").string());
    REQUIRE(run_apcs(made).status == 0);
    REQUIRE(std::filesystem::exists(folder / "frames" / "inb012.dat"));
    std::vector<std::string> nested = files;
    nested.push_back((folder / "nowhere" / "frames").string());
    const auto result = run_apcs(nested);
    REQUIRE(result.status == 1);
    REQUIRE(result.err.find("cannot be made: " + (folder / "nowhere").string() + " is not a folder") != std::string::npos);
    REQUIRE_FALSE(std::filesystem::exists(folder / "nowhere"));
}

TEST_CASE("apcs inbetween prints frames 0 to T with the padded count", "[cli][inbetween]")
{
    const TempFolder folder;
    folder.write("gb.dat", "0 0\n2 0\n2 4\n");
    folder.write("ge.dat", "0 0\n4 0\n4 4\n0 4\n8 8\n");
    const auto result = run_apcs({"inbetween", (folder / "gb.dat").string(), (folder / "ge.dat").string(), "--frames",
                                  "2", "--law", "linear", "--pad", "end", "--print"});
    REQUIRE(result.status == 0);
    REQUIRE(result.out == "# frame 0\n"
                          "0.000000 0.000000 0.000000\n2.000000 0.000000 0.000000\n2.000000 4.000000 0.000000\n"
                          "2.000000 4.000000 0.000000\n2.000000 4.000000 0.000000\n"
                          "# frame 1\n"
                          "0.000000 0.000000 0.000000\n3.000000 0.000000 0.000000\n3.000000 4.000000 0.000000\n"
                          "1.000000 4.000000 0.000000\n5.000000 6.000000 0.000000\n"
                          "# frame 2\n"
                          "0.000000 0.000000 0.000000\n4.000000 0.000000 0.000000\n4.000000 4.000000 0.000000\n"
                          "0.000000 4.000000 0.000000\n8.000000 8.000000 0.000000\n");
}

TEST_CASE("apcs inbetween writes the in-between files and never a key file", "[cli][inbetween]")
{
    const TempFolder folder;
    folder.write("gb.dat", "0 0\n2 0\n");
    folder.write("inb001.dat", "1 1\n3 3\n");
    const auto refused = run_apcs({"inbetween", (folder / "gb.dat").string(), (folder / "inb001.dat").string(),
                                   "--frames", "3", "--out", folder.path().string()});
    REQUIRE(refused.status == 1);
    REQUIRE(refused.err.find("key files are never written") != std::string::npos);
    REQUIRE(test::read_all(folder / "inb001.dat") == "1 1\n3 3\n");

    folder.write("ge.dat", "1 1\n3 3\n");
    const auto written = run_apcs({"inbetween", (folder / "gb.dat").string(), (folder / "ge.dat").string(), "--frames",
                                   "3", "--law", "ease-in-out", "--out", folder.path().string()});
    REQUIRE(written.status == 0);
    REQUIRE(std::filesystem::exists(folder / "inb002.dat"));
    REQUIRE(std::filesystem::exists(folder / "inb001.bak")); // the old inb001.dat, kept
}

TEST_CASE("a run with fewer in-betweens says on stderr which older ones it left, and keeps them",
          "[cli][inbetween]")
{
    const TempFolder folder;
    folder.write("gb.dat", "0 0\n2 0\n");
    folder.write("ge.dat", "1 1\n3 3\n");
    const auto run = [&](const char* frames) {
        return run_apcs({"inbetween", (folder / "gb.dat").string(), (folder / "ge.dat").string(), "--frames", frames,
                         "--out", folder.path().string()});
    };
    const auto longer = run("6");
    REQUIRE(longer.status == 0);
    REQUIRE(longer.err.find("earlier run") == std::string::npos);
    REQUIRE(std::filesystem::exists(folder / "inb005.dat"));
    const auto shorter = run("3");
    REQUIRE(shorter.status == 0);
    REQUIRE(shorter.err == "apcs: " + (folder / "inb003.dat").string() + " to " + (folder / "inb005.dat").string() +
                               " (3 files) are from an earlier run (not rewritten)\n");
    REQUIRE(std::filesystem::exists(folder / "inb005.dat"));
}

TEST_CASE("apcs fit --png draws all frames overlaid and writes no in-between file unless --out asks", "[cli][fit][png]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const auto pictured = run_apcs({"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                    (folder / "way1.dat").string(), (folder / "way4.dat").string(), "--inbetweens",
                                    "3", "--png", (folder / "all.png").string(), "--png-raw",
                                    (folder / "raw.png").string()});
    REQUIRE(pictured.status == 0);
    const test::GreyPicture monitor = test::grey_picture(test::read_all(folder / "all.png"));
    CHECK(monitor.width == 720);
    CHECK(monitor.height == 522);
    const test::GreyPicture raw = test::grey_picture(test::read_all(folder / "raw.png"));
    CHECK(raw.width == 720);
    CHECK(raw.height == 348);
    CHECK_FALSE(std::filesystem::exists(folder / "inb001.dat"));

    const auto both = run_apcs({"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                (folder / "way1.dat").string(), (folder / "way4.dat").string(), "--inbetweens", "3",
                                "--png", (folder / "again.png").string(), "--out", folder.path().string()});
    REQUIRE(both.status == 0);
    CHECK(std::filesystem::exists(folder / "again.png"));
    CHECK(std::filesystem::exists(folder / "inb003.dat"));
    CHECK_FALSE(std::filesystem::exists(folder / "inb004.dat"));
}

TEST_CASE("the overlay of more frames lights more pixels: every frame is drawn", "[cli][inbetween][png]")
{
    const TempFolder folder;
    // A vertical bar moving right: each frame is its own column of pixels.
    folder.write("gb.dat", "0 0 0\n0 0 10\n");
    folder.write("ge.dat", "0 20 0\n0 20 10\n");
    const auto lit_pixels = [&](const std::string& frames) {
        const auto name = (folder / ("f" + frames + ".png")).string();
        const auto result = run_apcs({"inbetween", (folder / "gb.dat").string(), (folder / "ge.dat").string(),
                                      "--frames", frames, "--view", "front", "--png-raw", name});
        REQUIRE(result.status == 0);
        const test::GreyPicture picture = test::grey_picture(test::read_all(name));
        std::size_t lit = 0;
        for (png_uint_32 y = 0; y < picture.height; ++y)
            for (png_uint_32 x = 0; x < picture.width; ++x)
                if (picture.lit(x, y))
                    ++lit;
        return lit;
    };
    const std::size_t two = lit_pixels("1");
    const std::size_t five = lit_pixels("4");
    // Three more bars of the same height; the caption's digits differ by a few pixels only.
    CHECK(five > two + 3 * 100);
    CHECK_FALSE(std::filesystem::exists(folder / "inb001.dat"));
}

TEST_CASE("apcs fit takes each path file's SLOPES — an explicit --slopes overrides them (SPEC 2.1)", "[cli][fit][slopes]")
{
    // The first path (0,0,0) → (0,0,10) with SLOPES 0 0 has zero end tangents: P(u) = F2(u)·(0,0,10), so
    // with 4 samples they lie at z = 0, 1.5625, 5, 8.4375, 10 (F2(1/4) = 0.15625), and in-between 1 of 3
    // (chord length 2.5) is the sample at 1.5625. The last path has no SLOPES: slopes 1 1, a straight
    // even line, in-between 1 at z = 2.5. --slopes 1 1 puts the first at 2.5 too.
    const TempFolder folder;
    folder.write("key1.dat", "0 0 0\n0 1 0\n");
    folder.write("key2.dat", "0 0 10\n0 1 10\n");
    folder.write("first.dat", "SLOPES 0 0\n0 0 0\n0 0 10\n");
    folder.write("last.dat", "0 1 0\n0 1 10\n");
    std::vector<std::string> arguments{"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                       (folder / "first.dat").string(), (folder / "last.dat").string(),
                                       "--inbetweens", "3", "--samples", "4", "--print"};
    const auto from_files = run_apcs(arguments);
    REQUIRE(from_files.status == 0);
    CHECK(from_files.out.find("# frame 1\n0.000000 0.000000 1.562500\n0.000000 1.000000 2.500000\n") !=
          std::string::npos);
    arguments.insert(arguments.end(), {"--slopes", "1", "1"});
    const auto overridden = run_apcs(arguments);
    REQUIRE(overridden.status == 0);
    CHECK(overridden.out.find("# frame 1\n0.000000 0.000000 2.500000\n0.000000 1.000000 2.500000\n") !=
          std::string::npos);
}

TEST_CASE("apcs fit --surface ferguson: the end points follow their paths, the option is checked", "[cli][fit][ferguson]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const std::vector<std::string> files{"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                         (folder / "way1.dat").string(), (folder / "way4.dat").string()};
    std::vector<std::string> blend = files;
    blend.insert(blend.end(), {"--print", "--surface", "blend"});
    std::vector<std::string> ferguson = files;
    ferguson.insert(ferguson.end(), {"--print", "--surface", "ferguson"});
    const auto by_blend = run_apcs(blend);
    const auto by_ferguson = run_apcs(ferguson);
    REQUIRE(by_blend.status == 0);
    REQUIRE(by_ferguson.status == 0);
    CHECK(by_blend.out == run_apcs({files[0], files[1], files[2], files[3], files[4], "--print"}).out);
    CHECK(by_ferguson.out != by_blend.out);
    // Frame 1's first point is way1's in-between 1 either way.
    const std::string frame1 = "# frame 1\n";
    const std::size_t at = by_blend.out.find(frame1) + frame1.size();
    const std::string first_line = by_blend.out.substr(at, by_blend.out.find('\n', at) - at + 1);
    CHECK(by_ferguson.out.find(frame1 + first_line) != std::string::npos);
    std::vector<std::string> wrong = files;
    wrong.insert(wrong.end(), {"--surface", "coons"});
    CHECK(run_apcs(wrong).status == 2);
}

TEST_CASE("apcs fit names each path whose frames freeze", "[cli][fit]")
{
    // Straight paths of 4 samples, 3 in-betweens at acceleration +1: in-between 1 lands on KEY1's
    // sample (1 − cos(π/8) = 0.076 of the length is nearer 0 than 1/4).
    const TempFolder folder;
    const auto key1 = folder.write("key1.dat", "0 0 0\n0 0 10\n");
    const auto key2 = folder.write("key2.dat", "0 8 0\n0 8 10\n");
    const auto first = folder.write("way1.dat", "0 0 0\n0 8 0\n");
    const auto last = folder.write("way2.dat", "0 0 10\n0 8 10\n");
    const auto result = run_apcs({"fit", key1.string(), key2.string(), first.string(), last.string(), "--samples",
                                  "4", "--inbetweens", "3", "--accel", "1", "--print"});
    REQUIRE(result.status == 0);
    REQUIRE(result.err == "apcs: " + first.string() + ": frames will freeze at KEY1=1\napcs: " + last.string() +
                              ": frames will freeze at KEY1=1\n");
    // At acceleration 0 the frames are 1/4, 1/2, 3/4 of the way: nothing to say.
    REQUIRE(run_apcs({"fit", key1.string(), key2.string(), first.string(), last.string(), "--samples", "4",
                      "--inbetweens", "3", "--print"})
                .err.empty());
}
