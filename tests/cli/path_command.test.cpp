#include "apcs/cli/command_line.h"
#include "apcs/cli/path_command.h"

#include "support/png_pixels.h"
#include "support/temp_folder.h"

#include "support/run_apcs.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <vector>

using namespace apcs;
using test::TempFolder;

using test::run_apcs;

TEST_CASE("apcs path --print writes the curve then the in-betweens, worked by hand", "[cli][path]")
{
    const TempFolder folder;
    // Two control points, slopes 1 1: P(u) = (4u, 0, 2u); 4 samples give x = 0, 1, 2, 3, 4 and
    // 3 in-betweens at a = 0 fall on L·j/4, the samples 1, 2 and 3.
    const auto file = folder.write("ani1.dat", "0 0 0\n4 0 2\n");
    const auto result = run_apcs({"path", file.string(), "--samples", "4", "--inbetweens", "3", "--print"});
    REQUIRE(result.status == 0);
    REQUIRE(result.err.empty());
    REQUIRE(result.out == "# curve\n"
                          "0.000000 0.000000 0.000000\n"
                          "1.000000 0.000000 0.500000\n"
                          "2.000000 0.000000 1.000000\n"
                          "3.000000 0.000000 1.500000\n"
                          "4.000000 0.000000 2.000000\n"
                          "# inbetweens\n"
                          "1.000000 0.000000 0.500000\n"
                          "2.000000 0.000000 1.000000\n"
                          "3.000000 0.000000 1.500000\n");
}

TEST_CASE("apcs path takes the file's SLOPES line unless --slopes is given, worked by hand", "[cli][path]")
{
    const TempFolder folder;
    // SLOPES 0 0: both end tangents vanish, P(u) = F2(u)·(4, 0, 2) with F2 = 3u² − 2u³: 0.15625,
    // 0.5, 0.84375 at u = 1/4, 1/2, 3/4. The targets 1/4, 1/2, 3/4 of the length take the nearest
    // samples: 0.15625, 0.5 and 0.84375 of the way.
    const auto file = folder.write("ani1.dat", "SLOPES 0 0\n0 0 0\n4 0 2\n");
    const auto own = run_apcs({"path", file.string(), "--samples", "4", "--inbetweens", "3", "--print"});
    REQUIRE(own.status == 0);
    REQUIRE(own.out == "# curve\n"
                       "0.000000 0.000000 0.000000\n"
                       "0.625000 0.000000 0.312500\n"
                       "2.000000 0.000000 1.000000\n"
                       "3.375000 0.000000 1.687500\n"
                       "4.000000 0.000000 2.000000\n"
                       "# inbetweens\n"
                       "0.625000 0.000000 0.312500\n"
                       "2.000000 0.000000 1.000000\n"
                       "3.375000 0.000000 1.687500\n");
    // --slopes 1 1 overrides the line: the evenly moving path of the test above.
    const auto given = run_apcs({"path", file.string(), "--samples", "4", "--inbetweens", "3", "--slopes", "1", "1"});
    REQUIRE(given.status == 0);
    REQUIRE(given.out.find("1.000000 0.000000 0.500000\n") != std::string::npos);
}

TEST_CASE("apcs path agrees with the Catmull-Rom midpoint to 1e-9", "[cli][path]")
{
    const TempFolder folder;
    const auto file = folder.write("ani1.dat", "0 0 0\n1 2 1\n4 3 -1\n6 0 2\n");
    const auto result = run_apcs({"path", file.string(), "--samples", "2", "--inbetweens", "0"});
    REQUIRE(result.status == 0);
    std::istringstream lines(result.out);
    std::string line;
    std::vector<Vec3> curve;
    while (std::getline(lines, line)) {
        Vec3 point;
        if (std::sscanf(line.c_str(), "%lf %lf %lf", &point.x, &point.y, &point.z) == 3)
            curve.push_back(point);
    }
    REQUIRE(curve.size() == 7);
    // (−P0 + 9P1 + 9P2 − P3)/16 = (39/16, 45/16, −2/16) = (2.4375, 2.8125, −0.125).
    REQUIRE(distance(curve[3], {2.4375, 2.8125, -0.125}) < 1e-9);
}

TEST_CASE("a 7-column path file uses its own t c b a and a 3-column one the global options", "[cli][path]")
{
    const TempFolder folder;
    const auto own = folder.write("own.dat", "0 0 0 1 0 0 0\n1 2 0 1 0 0 0\n3 0 0 1 0 0 0\n");
    const auto plain = folder.write("plain.dat", "0 0 0\n1 2 0\n3 0 0\n");
    const auto with_own = run_apcs({"path", own.string(), "--slopes", "0", "0"});
    const auto with_global = run_apcs({"path", plain.string(), "--slopes", "0", "0", "--tension", "1"});
    const auto with_default = run_apcs({"path", plain.string(), "--slopes", "0", "0"});
    REQUIRE(with_own.out == with_global.out);
    REQUIRE(with_own.out != with_default.out);
}

TEST_CASE("an option value too small for a double is 0, as in a .dat file", "[cli][path]")
{
    const TempFolder folder;
    const auto plain = folder.write("plain.dat", "0 0 0\n1 2 0\n3 0 0\n");
    const auto tiny = run_apcs({"path", plain.string(), "--slopes", "1e-400", "0", "--tension", "-1e-400"});
    const auto zero = run_apcs({"path", plain.string(), "--slopes", "0", "0", "--tension", "0"});
    REQUIRE(tiny.err.empty());
    REQUIRE(tiny.status == 0);
    REQUIRE(tiny.out == zero.out);
}

TEST_CASE("apcs path output is deterministic", "[cli][path]")
{
    const TempFolder folder;
    const auto file = folder.write("ani1.dat", "0 0 0\n1 2 1\n4 3 -1\n6 0 2\n");
    const auto first = run_apcs({"path", file.string(), "--accel", "0.4"});
    const auto second = run_apcs({"path", file.string(), "--accel", "0.4"});
    // Two runs that fail alike would print the same nothing: both must succeed and print the path.
    REQUIRE(first.status == 0);
    REQUIRE(first.err.empty());
    REQUIRE(first.out.find("# inbetweens\n") != std::string::npos);
    REQUIRE(second.status == 0);
    REQUIRE(second.out == first.out);
}

TEST_CASE("a bad path file is exit 1 with FILE:LINE on stderr and nothing on stdout", "[cli][path]")
{
    const TempFolder folder;
    const auto file = folder.write("bad.dat", "0 0 0\n1 x 1\n");
    const auto result = run_apcs({"path", file.string(), "--print"});
    REQUIRE(result.status == 1);
    REQUIRE(result.out.empty());
    REQUIRE(result.err == file.string() + ":2: expected a number, found 'x'\n");
}

TEST_CASE("more in-betweens than samples warn that frames will freeze", "[cli][path]")
{
    const TempFolder folder;
    const auto file = folder.write("ani1.dat", "0 0 0\n4 0 2\n");
    const auto result = run_apcs({"path", file.string(), "--samples", "2", "--inbetweens", "5"});
    REQUIRE(result.status == 0);
    REQUIRE(result.err ==
            "apcs: " + file.string() + ": frames will freeze at KEY1=1, 2=3, 3=4, 5=KEY2 (5 in-betweens, 2 curve samples)\n");
}

TEST_CASE("apcs path --png draws the path screen as a 720x522 PNG", "[cli][path][png]")
{
    const TempFolder folder;
    const auto file = folder.write("ani1.dat", "0 0 0\n3 -4 5\n0 0 10\n");
    const auto png = folder / "path.png";
    const auto result = run_apcs({"path", file.string(), "--png", png.string(), "--theta", "0", "--phi", "90"});
    REQUIRE(result.status == 0);
    REQUIRE(result.out.empty()); // --png alone prints nothing
    const std::string bytes = test::read_all(png);
    REQUIRE(bytes.substr(1, 3) == "PNG");
    // IHDR: width and height, big-endian, at bytes 16 and 20.
    const auto be32 = [&](std::size_t at) {
        return (static_cast<unsigned char>(bytes[at]) << 24) | (static_cast<unsigned char>(bytes[at + 1]) << 16) |
               (static_cast<unsigned char>(bytes[at + 2]) << 8) | static_cast<unsigned char>(bytes[at + 3]);
    };
    REQUIRE(be32(16) == 720);
    REQUIRE(be32(20) == 522);
    const auto both = run_apcs({"path", file.string(), "--png", png.string(), "--print"});
    REQUIRE(both.out.starts_with("# curve\n"));
}

namespace {

// Width over height of the lit pixels above the staff (the drawing area is the top 7/10).
double drawing_aspect(const test::GreyPicture& picture)
{
    png_uint_32 left = picture.width, right = 0, top = picture.height, bottom = 0;
    // Inside the drawing area's frame (2 pixels in from the picture's edge).
    for (png_uint_32 y = 4; y < picture.height * 7 / 10; ++y)
        for (png_uint_32 x = 4; x + 4 < picture.width; ++x)
            if (picture.lit(x, y)) {
                left = std::min(left, x);
                right = std::max(right, x);
                top = std::min(top, y);
                bottom = std::max(bottom, y);
            }
    REQUIRE(right > left);
    REQUIRE(bottom > top);
    return static_cast<double>(right - left) / static_cast<double>(bottom - top);
}

} // namespace

TEST_CASE("a unit square seen face-on is square in --png and 1.5:1 in --png-raw", "[cli][path][png]")
{
    const TempFolder folder;
    // Tension 1 everywhere: straight sides through the four corners.
    const auto square = folder.write("square.dat", "0 0 0 1 0 0 0\n1 0 0 1 0 0 0\n1 1 0 1 0 0 0\n0 1 0 1 0 0 0\n0 0 0 1 0 0 0\n");
    const auto monitor = folder / "monitor.png";
    const auto raw = folder / "raw.png";
    const auto result =
        run_apcs({"path", square.string(), "--view", "top", "--png", monitor.string(), "--png-raw", raw.string()});
    REQUIRE(result.status == 0);
    const test::GreyPicture seen = test::grey_picture(test::read_all(monitor));
    const test::GreyPicture bare = test::grey_picture(test::read_all(raw));
    REQUIRE(seen.height == 522);
    REQUIRE(bare.height == 348);
    CHECK(drawing_aspect(seen) == Approx(1.0).epsilon(0.03));
    CHECK(drawing_aspect(bare) == Approx(1.5).epsilon(0.03));
}

TEST_CASE("the views top, front and side are theta/phi -90/0, 0/90 and -90/90", "[cli][path][png]")
{
    const TempFolder folder;
    const auto file = folder.write("ani1.dat", "0 0 0\n3 -4 5\n0 2 10\n");
    const auto picture = [&](std::vector<std::string> view) {
        std::vector<std::string> arguments{"path", file.string(), "--png", (folder / "p.png").string()};
        arguments.insert(arguments.end(), view.begin(), view.end());
        REQUIRE(run_apcs(arguments).status == 0);
        return test::read_all(folder / "p.png");
    };
    CHECK(picture({"--view", "top"}) == picture({"--theta", "-90", "--phi", "0"}));
    CHECK(picture({"--view", "front"}) == picture({"--theta", "0", "--phi", "90"}));
    CHECK(picture({"--view", "side"}) == picture({"--theta", "-90", "--phi", "90"}));
    CHECK(picture({"--view", "top"}) != picture({"--view", "front"}));
}

TEST_CASE("a picture's name must end in .png, and a view preset excludes theta and phi", "[cli][path][png]")
{
    const TempFolder folder;
    const auto file = folder.write("ani1.dat", "0 0 0\n3 -4 5\n");
    const auto svg = run_apcs({"path", file.string(), "--png", (folder / "x.svg").string()});
    CHECK(svg.status == 2);
    CHECK(svg.err.find("a PNG file's name ends in .png") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(folder / "x.svg"));
    CHECK(run_apcs({"path", file.string(), "--png-raw", (folder / "x.PNG").string()}).status == 0);
    CHECK(run_apcs({"path", file.string(), "--view", "top", "--theta", "3"}).status == 2);
    CHECK(run_apcs({"path", file.string(), "--view", "diagonal"}).status == 2);
}
