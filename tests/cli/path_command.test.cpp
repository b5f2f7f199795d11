#include "apcs/cli/command_line.h"
#include "apcs/cli/path_command.h"

#include "support/temp_folder.h"

#include "support/run_apcs.h"

#include <catch2/catch.hpp>

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

TEST_CASE("apcs path output is deterministic", "[cli][path]")
{
    const TempFolder folder;
    const auto file = folder.write("ani1.dat", "0 0 0\n1 2 1\n4 3 -1\n6 0 2\n");
    REQUIRE(run_apcs({"path", file.string(), "--accel", "0.4"}).out == run_apcs({"path", file.string(), "--accel", "0.4"}).out);
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
    REQUIRE(result.err == "apcs: 5 in-betweens from 2 curve samples: frames will freeze\n");
}

TEST_CASE("apcs path --png draws the path screen as a 720x348 PNG", "[cli][path][png]")
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
    REQUIRE(be32(20) == 348);
    const auto both = run_apcs({"path", file.string(), "--png", png.string(), "--print"});
    REQUIRE(both.out.starts_with("# curve\n"));
}
