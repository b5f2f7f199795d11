#include "apcs/formats/dat_file.h"

#include <catch2/catch.hpp>

#include <string>

using namespace apcs;

namespace {

std::string rejection(const std::string& text, std::size_t minimum_points = 2)
{
    const Expected<DatFile> file = parse_dat(text, "key1.dat", minimum_points);
    REQUIRE_FALSE(file.has_value());
    return file.error().to_string();
}

DatFile accepted(const std::string& text)
{
    const Expected<DatFile> file = parse_dat(text, "key1.dat");
    if (!file)
        FAIL(file.error().to_string());
    return *file;
}

} // namespace

TEST_CASE("a plain file of 3-D points is one open part", "[formats][dat]")
{
    const DatFile file = accepted("0 0 0\n1 2 3\n4.5 -6 7e-1\n");
    REQUIRE(file.parts.size() == 1);
    REQUIRE(file.parts[0].closure == Closure::open);
    REQUIRE(file.parts[0].points.size() == 3);
    REQUIRE(file.parts[0].points[2].position == Vec3{4.5, -6, 0.7});
    REQUIRE_FALSE(file.parts[0].points[2].staff.has_value());
    REQUIRE(file.parts[0].points[2].line == 3);
}

TEST_CASE("DOS-style forms are accepted", "[formats][dat]")
{
    SECTION("CRLF line ends and a trailing Ctrl-Z")
    {
        const DatFile file = accepted("0 0 0\r\n1 1 1\r\n\x1A");
        REQUIRE(file.point_count() == 2);
    }
    SECTION("a UTF-8 byte-order mark, tabs and exponents")
    {
        const DatFile file = accepted("\xEF\xBB\xBF" "1e2\t-2.5E-1\t+3\n\t4 5 6\n");
        REQUIRE(file.parts[0].points[0].position == Vec3{100, -0.25, 3});
    }
    SECTION("2-D points get z = 0")
    {
        const DatFile file = accepted("1 2\n3 4\n");
        REQUIRE(file.parts[0].points[1].position == Vec3{3, 4, 0});
    }
    SECTION("comments with ';' or '#' and blank lines")
    {
        const DatFile file = accepted("; a key frame\n\n# another comment\n1 2 3 ; trailing\n4 5 6 # too\n   \n");
        REQUIRE(file.point_count() == 2);
    }
    SECTION("a count line that matches")
    {
        const DatFile file = accepted("; header\n3\n0 0 0\n1 1 1\n2 2 2\n");
        REQUIRE(file.point_count() == 3);
    }
    SECTION("seven columns carry t c b a")
    {
        const DatFile file = accepted("0 0 0 0.5 -0.5 1 -1\n1 1 1\n");
        REQUIRE(file.parts[0].points[0].staff == StaffValues{0.5, -0.5, 1, -1});
        REQUIRE_FALSE(file.parts[0].points[1].staff.has_value());
    }
    SECTION("PART lines, OPEN, CLOSED and ends that meet")
    {
        const DatFile file = accepted("part body open\n0 0\n1 0\nPART apple CLOSED\n5 5\n6 5\n6 6\n"
                                      "PART ring\n0 0\n1 0\n1 1\n0 0\n");
        REQUIRE(file.parts.size() == 3);
        REQUIRE(file.parts[0].name == "body");
        REQUIRE(file.parts[0].closure == Closure::open);
        REQUIRE(file.parts[1].closure == Closure::closed);
        REQUIRE(file.parts[2].closure == Closure::closed);
    }
}

TEST_CASE("old Macintosh files with lone CR line ends read like their LF twins", "[formats][dat]")
{
    const DatFile mac = accepted("; key frame\r0 0 0\r1 2 3\r\r4 5 6\r");
    const DatFile unix_twin = accepted("; key frame\n0 0 0\n1 2 3\n\n4 5 6\n");
    REQUIRE(mac.point_count() == 3);
    REQUIRE(mac.parts[0].points[2].position == unix_twin.parts[0].points[2].position);
    REQUIRE(mac.parts[0].points[2].line == 5);
    REQUIRE(rejection("0 0\r1 one\r") == "key1.dat:2: expected a number, found 'one'");
    REQUIRE(rejection("0 0\r\n1 1\r2 x\n") == "key1.dat:3: expected a number, found 'x'");
    REQUIRE(rejection("0 0\r\x1A" "1 1\r") ==
            "key1.dat:2: Ctrl-Z (end of file) followed by more data; expected it only at the end");
}

TEST_CASE("magnitudes below the smallest double read as zero, as subnormal ones read as themselves", "[formats][dat]")
{
    const DatFile file = accepted("1e-310 -1e-400\n0.000001e-999 1e-99999999999999999999999\n");
    REQUIRE(file.parts[0].points[0].position.x == 1e-310);
    REQUIRE(file.parts[0].points[0].position.y == 0.0);
    REQUIRE(file.parts[0].points[1].position == Vec3{0, 0, 0});
    REQUIRE(rejection("0 0 0\n1 1 1000e306\n") == "key1.dat:2: expected a finite number, found '1000e306'");
    REQUIRE(rejection("0 0 0\n1 1 1e9999999999999999999\n") ==
            "key1.dat:2: expected a finite number, found '1e9999999999999999999'");
    REQUIRE(rejection("0 0 0\n1 1 1e-400x\n") == "key1.dat:2: expected a number, found '1e-400x'");
}

TEST_CASE("every malformed input is rejected with FILE:LINE and what was expected", "[formats][dat]")
{
    REQUIRE(rejection("") == "key1.dat: expected at least 2 points, found 0");
    REQUIRE(rejection("; only a comment\n\n") == "key1.dat: expected at least 2 points, found 0");
    REQUIRE(rejection("1 2 3\n") == "key1.dat: expected at least 2 points, found 1");
    REQUIRE(rejection("0 0 0\n1 one 2\n") == "key1.dat:2: expected a number, found 'one'");
    REQUIRE(rejection("0 0 0\n1 2 3 4\n") ==
            "key1.dat:2: expected a point of 2, 3 or 7 numbers (x y [z] [t c b a]), found 4 fields");
    REQUIRE(rejection("0 0 0\n1\n") ==
            "key1.dat:2: expected a point of 2, 3 or 7 numbers (x y [z] [t c b a]), found 1 fields");
    REQUIRE(rejection("0 0 0\nnan 1 1\n") == "key1.dat:2: expected a finite number, found 'nan'");
    REQUIRE(rejection("0 0 0\n1 inf 1\n") == "key1.dat:2: expected a finite number, found 'inf'");
    REQUIRE(rejection("0 0 0\n1 1 1e999\n") == "key1.dat:2: expected a finite number, found '1e999'");
    REQUIRE(rejection("0 0 0\n1 2000000000 1\n") ==
            "key1.dat:2: number '2000000000' is out of range; expected |value| <= 1e9");
    REQUIRE(rejection("0 0 0 1.5 0 0 0\n1 1 1\n") == "key1.dat:1: tension '1.5' is outside [-1, 1]");
    REQUIRE(rejection("0 0 0 0 -2 0 0\n1 1 1\n") == "key1.dat:1: continuity '-2' is outside [-1, 1]");
    REQUIRE(rejection("0 0 0 0 0 1.01 0\n1 1 1\n") == "key1.dat:1: bias '1.01' is outside [-1, 1]");
    REQUIRE(rejection("0 0 0 0 0 0 -1.5\n1 1 1\n") == "key1.dat:1: acceleration '-1.5' is outside [-1, 1]");
    REQUIRE(rejection("3\n0 0\n1 1\n") == "key1.dat:1: the count line says 3 points but 2 follow");
    REQUIRE(rejection("-3\n0 0\n1 1\n") ==
            "key1.dat:1: expected a point count (a whole number from 0 to 1000000) or a point of 2, 3 or 7 numbers, "
            "found '-3'");
    REQUIRE(rejection("2000000\n0 0\n1 1\n") == "key1.dat:1: point count 2000000 is over the limit of 1000000");
    REQUIRE(rejection(std::string("0 0\n1 1\n2 2\0 3\n", 15)) == "key1.dat:3: NUL byte; expected a text file");
    REQUIRE(rejection("0 0\n1 1\n" + std::string(5000, ' ') + "\n") ==
            "key1.dat:3: line is 5000 bytes long; expected at most 4096");
    REQUIRE(rejection("0 0\n\x1A" "1 1\n") ==
            "key1.dat:2: Ctrl-Z (end of file) followed by more data; expected it only at the end");
    REQUIRE(rejection("\x7F\x45LF\x02\x01\n0 0\n") == "key1.dat:1: expected a point count (a whole number from 0 to "
                                                      "1000000) or a point of 2, 3 or 7 numbers, found '\\x7FELF\\x02\\x01'");
    REQUIRE(rejection("PART\n0 0\n1 1\n") == "key1.dat:1: expected 'PART name' or 'PART name OPEN|CLOSED'");
    REQUIRE(rejection("PART a b c\n0 0\n1 1\n") == "key1.dat:1: expected 'PART name' or 'PART name OPEN|CLOSED'");
    REQUIRE(rejection("PART a SHUT\n0 0\n1 1\n") ==
            "key1.dat:1: expected OPEN or CLOSED after the part name, found 'SHUT'");
    REQUIRE(rejection("PART a\nPART b\n0 0\n1 1\n") == "key1.dat:1: part 'a' has no points; expected at least one");
    REQUIRE(rejection("0 0\n1 1\nPART tail\n") == "key1.dat:3: part 'tail' has no points; expected at least one");
}

TEST_CASE("more than a million points are refused as soon as the limit is passed", "[formats][dat]")
{
    std::string text;
    text.reserve((max_dat_points + 1) * 4);
    for (std::size_t i = 0; i <= max_dat_points; ++i)
        text += "1 1\n";
    REQUIRE(rejection(text) == "key1.dat:1000001: more than 1000000 points; expected at most that many");
}

TEST_CASE("written files read back to the same points, parts and staff values", "[formats][dat]")
{
    DatFile file;
    file.parts.push_back({"body", Closure::open, {{{0.1, -2, 3e-7}, StaffValues{0.25, -0.5, 0, 1}, 0},
                                                 {{1.0 / 3.0, 2, 1e8}, std::nullopt, 0}}});
    file.parts.push_back({"", Closure::closed, {{{5, 5, 0}, std::nullopt, 0}, {{6, 5, -0.0}, std::nullopt, 0}}});
    const std::string text = format_dat(file);
    REQUIRE(text == "PART body OPEN\n0.1 -2 3e-07 0.25 -0.5 0 1\n0.3333333333333333 2 1e+08\n"
                    "PART P2 CLOSED\n5 5 0\n6 5 0\n");
    const DatFile again = accepted(text);
    REQUIRE(again.parts.size() == 2);
    REQUIRE(again.parts[0].points[1].position.x == 1.0 / 3.0);
    REQUIRE(again.parts[0].points[0].staff == StaffValues{0.25, -0.5, 0, 1});
    REQUIRE(again.parts[1].closure == Closure::closed);
}

TEST_CASE("a single open unnamed part is written without a PART line", "[formats][dat]")
{
    DatFile file;
    file.parts.push_back({"", Closure::open, {{{1, 2, 3}, std::nullopt, 0}, {{4, 5, 6}, std::nullopt, 0}}});
    REQUIRE(format_dat(file) == "1 2 3\n4 5 6\n");
}

TEST_CASE("a path file's SLOPES S0 S1 line is read before the first point and written first", "[formats][dat][slopes]")
{
    const DatFile file = accepted("; way4 as adjusted\nslopes 0.5 1\n0 6 10\n0 5 0\n");
    REQUIRE(file.slopes.has_value());
    CHECK(file.slopes->start == 0.5);
    CHECK(file.slopes->end == 1.0);
    CHECK_FALSE(accepted("0 0 0\n1 1 1\n").slopes.has_value());
    CHECK(format_dat(file) == "SLOPES 0.5 1\n0 6 10\n0 5 0\n");
    CHECK(rejection("0 0 0\nSLOPES 1 1\n1 1 1\n") == "key1.dat:2: SLOPES after a point; expected it before the first point");
    CHECK(rejection("SLOPES 1 1\nSLOPES 1 1\n0 0 0\n1 1 1\n") == "key1.dat:2: a second SLOPES line; expected one at most");
    CHECK(rejection("SLOPES 1.5 1\n0 0 0\n1 1 1\n") == "key1.dat:1: expected an end slope in [0, 1], found '1.5'");
    CHECK(rejection("SLOPES 1\n0 0 0\n1 1 1\n") == "key1.dat:1: expected 'SLOPES S0 S1', two end slopes in [0, 1]");
}
