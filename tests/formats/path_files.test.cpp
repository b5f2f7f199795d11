#include "apcs/formats/path_files.h"

#include <catch2/catch.hpp>

using namespace apcs;

namespace {

// Open keys of two points each: the first graphic point goes (0,0,0) → (0,0,10), the last one
// (0,6,0) → (0,5,0).
EqualisedKeys two_point_keys()
{
    Graphic key1;
    key1.parts.push_back({"", Closure::open, {{0, 0, 0}, {0, 6, 0}}});
    Graphic key2;
    key2.parts.push_back({"", Closure::open, {{0, 0, 10}, {0, 5, 0}}});
    return {key1, key2};
}

DatFile path_file(const std::string& text) { return *parse_dat(text, "way.dat"); }

} // namespace

TEST_CASE("a path from the first point's KEY1 to its KEY2 position gives its control points", "[formats][path-files]")
{
    const StaffValues defaults{0.5, 0, 0, -0.25};
    const Expected<ControlPoints> points =
        point_path_from(path_file("0 0 0\n3 -4 5 0.1 0.2 0.3 0.4\n0 0 10\n"), "way1.dat", PathEnd::first,
                        two_point_keys(), defaults);
    REQUIRE(points.has_value());
    REQUIRE(points->size() == 3);
    REQUIRE(points->front().staff == defaults);
    REQUIRE((*points)[1].position == Vec3{3, -4, 5});
    REQUIRE((*points)[1].staff == StaffValues{0.1, 0.2, 0.3, 0.4});
}

TEST_CASE("a path is checked against the ends of its own graphic point", "[formats][path-files]")
{
    const DatFile last_path = path_file("0 6 0\n-3 10 5\n0 5 0\n");
    REQUIRE(point_path_from(last_path, "way4.dat", PathEnd::last, two_point_keys(), {}).has_value());
    const Expected<ControlPoints> as_first = point_path_from(last_path, "way4.dat", PathEnd::first, two_point_keys(), {});
    REQUIRE_FALSE(as_first.has_value());
    REQUIRE(as_first.error().to_string() ==
            "way4.dat:1: the path starts at (0, 6, 0); expected the first graphic point's KEY1 position (0, 0, 0)");
    const Expected<ControlPoints> wrong_end =
        point_path_from(path_file("0 6 0\n0 5 1\n"), "way4.dat", PathEnd::last, two_point_keys(), {});
    REQUIRE_FALSE(wrong_end.has_value());
    REQUIRE(wrong_end.error().to_string() ==
            "way4.dat:2: the path ends at (0, 5, 1); expected the last graphic point's KEY2 position (0, 5, 0)");
}

TEST_CASE("a path's end in a message has six significant digits, more only where six would show two points alike",
          "[formats][path-files]")
{
    // Issue 44: the path-end messages (the session's, apcs fit's, a scene's PATHS) printed up to
    // 17 digits, as 0.30000000000000004.
    REQUIRE(describe_point({0.1 + 0.2, 1.0 / 3.0, -0.0}) == "(0.3, 0.333333, 0)");
    REQUIRE(describe_point({1234567.0, -2e-7, 12.5}) == "(1.23457e+06, -2e-07, 12.5)");
    const Expected<ControlPoints> rounded =
        point_path_from(path_file("0 0.30000000000000004 0\n0 0 10\n"), "way1.dat", PathEnd::first, two_point_keys(), {});
    REQUIRE_FALSE(rounded.has_value());
    REQUIRE(rounded.error().to_string() ==
            "way1.dat:1: the path starts at (0, 0.3, 0); expected the first graphic point's KEY1 position (0, 0, 0)");
    // 100.0002 is refused (1e-6 of 100 is 1e-4) but is 100 in six digits: seven say it.
    Graphic key1;
    key1.parts.push_back({"", Closure::open, {{0, 100, 0}, {0, 6, 0}}});
    Graphic key2;
    key2.parts.push_back({"", Closure::open, {{0, 0, 10}, {0, 5, 0}}});
    const Expected<ControlPoints> near =
        point_path_from(path_file("0 100.0002 0\n0 0 10\n"), "way1.dat", PathEnd::first, {key1, key2}, {});
    REQUIRE_FALSE(near.has_value());
    REQUIRE(near.error().to_string() ==
            "way1.dat:1: the path starts at (0, 100.0002, 0); expected the first graphic point's KEY1 position (0, 100, 0)");
}

namespace {

ControlPoints points_of(const DatFile& file)
{
    return control_points_from(file, StaffValues{});
}

} // namespace

TEST_CASE("a rewritten path file keeps its comments, blank lines and line-end comments where they were", "[formats][path-files]")
{
    const std::string text = "; way1: the N's first point\n\n0 0 0 ; KEY1\n; the bend\n3 -4 5\n0 0 10\n; end\n";
    const DatFile file = *parse_dat(text, "way1.dat");
    ControlPoints points = points_of(file);
    points[1].staff.tension = 0.25;
    REQUIRE(format_path_file(text, file, points, file_origins(3)) ==
            "; way1: the N's first point\n\n0 0 0 0 0 0 0 ; KEY1\n; the bend\n3 -4 5 0.25 0 0 0\n0 0 10 0 0 0 0\n; end\n");
}

TEST_CASE("an inserted point gets a line after the point before it — a deleted one's comments stay", "[formats][path-files]")
{
    const std::string text = "0 0 0\n; before the bend\n3 -4 5\n; before the end\n0 0 10\n";
    const DatFile file = *parse_dat(text, "way1.dat");
    const ControlPoints read = points_of(file);
    const ControlPoints points{read[0], {{1, 1, 1}, {}}, read[2]};
    // Point 1 (3 -4 5) deleted, a new point inserted after the first.
    REQUIRE(format_path_file(text, file, points, std::vector<std::size_t>{0, new_point, 2}) ==
            "0 0 0 0 0 0 0\n1 1 1 0 0 0 0\n; before the bend\n; before the end\n0 0 10 0 0 0 0\n");
}

TEST_CASE("a CRLF path file stays CRLF — one without comments is exactly format_dat's text", "[formats][path-files]")
{
    const std::string crlf = "; header\r\n0 0 0\r\n0 0 10\r\n";
    const DatFile crlf_file = *parse_dat(crlf, "a.dat");
    REQUIRE(format_path_file(crlf, crlf_file, points_of(crlf_file), file_origins(2)) ==
            "; header\r\n0 0 0 0 0 0 0\r\n0 0 10 0 0 0 0\r\n");
    const std::string plain = "0 0 0\n3 -4 5 0.1 0.2 0.3 0.4\n0 0 10";
    const DatFile plain_file = *parse_dat(plain, "b.dat");
    REQUIRE(format_path_file(plain, plain_file, points_of(plain_file), file_origins(3)) ==
            format_dat(dat_from(points_of(plain_file))));
}

TEST_CASE("a rewritten path file carries the slopes it was adjusted with, in place of its old SLOPES line",
          "[formats][path-files][slopes]")
{
    const std::string text = "; way4\nSLOPES 1 1\n0 6 10 ; KEY1\n0 5 0\n";
    const DatFile file = *parse_dat(text, "way4.dat");
    REQUIRE(format_path_file(text, file, points_of(file), file_origins(2), EndSlopes{0.5, 1.0}) ==
            "; way4\nSLOPES 0.5 1\n0 6 10 0 0 0 0 ; KEY1\n0 5 0 0 0 0 0\n");
    const std::string without = "0 6 10\n0 5 0\n";
    const DatFile plain = *parse_dat(without, "ani4.dat");
    REQUIRE(format_path_file(without, plain, points_of(plain), file_origins(2), EndSlopes{0, 0.25}) ==
            "SLOPES 0 0.25\n0 6 10 0 0 0 0\n0 5 0 0 0 0 0\n");
}
