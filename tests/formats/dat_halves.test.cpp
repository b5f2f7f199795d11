// parse_dat's two halves (DatReading::in_halves, what a file of a megabyte or more gets) against
// reading in order: the same parts, points, lines and slopes to the bit, or the same first problem.
#include "apcs/formats/dat_file.h"

#include <catch2/catch.hpp>

#include <bit>
#include <string>
#include <vector>

using namespace apcs;

namespace {

// What a reading gave, as text that differs whenever the readings differ (numbers by their bits).
std::string outcome_of(const Expected<DatFile>& file)
{
    if (!file)
        return "problem " + file.error().to_string();
    std::string text;
    if (file->slopes)
        text += "slopes " + std::to_string(std::bit_cast<std::uint64_t>(file->slopes->start)) + " " +
                std::to_string(std::bit_cast<std::uint64_t>(file->slopes->end)) + "\n";
    for (const DatPart& part : file->parts) {
        text += "part '" + part.name + "' " + (part.closure == Closure::closed ? "closed" : "open") + "\n";
        for (const DatPoint& point : part.points) {
            text += std::to_string(point.line);
            for (const double value : {point.position.x, point.position.y, point.position.z})
                text += " " + std::to_string(std::bit_cast<std::uint64_t>(value));
            if (point.staff)
                for (const StaffLine line : staff_lines)
                    text += " " + std::to_string(std::bit_cast<std::uint64_t>((*point.staff)[line]));
            text += "\n";
        }
    }
    return text;
}

void require_same_readings(const std::string& text, std::size_t minimum_points = 2)
{
    INFO("text: " << text.substr(0, 200));
    const std::string in_order = outcome_of(parse_dat(text, "way1.dat", minimum_points, DatReading::in_order));
    const std::string in_halves = outcome_of(parse_dat(text, "way1.dat", minimum_points, DatReading::in_halves));
    REQUIRE(in_halves == in_order);
}

// `lines` point lines "k 2k 0.5", line `fault_line` (from 1) replaced by `fault`.
std::string points_with(int lines, int fault_line, const std::string& fault, const std::string& line_end = "\n")
{
    std::string text;
    for (int k = 1; k <= lines; ++k)
        text += (k == fault_line ? fault : std::to_string(k) + " " + std::to_string(2 * k) + " 0.5") + line_end;
    return text;
}

} // namespace

TEST_CASE("a file read in halves gives the points and lines read in order gives", "[formats][dat][halves]")
{
    const std::vector<std::string> texts{
        "0 0 0\n1 2 3\n4.5 -6 7e-1\n",
        "0 0 0\r\n1 2 3\r\n4 5 6\r\n7 8 9\r\n",
        "0 0 0\r1 2 3\r4 5 6\r7 8 9\r",
        "0 0 0\n1 2 3\r\n4 5 6\r7 8 9",
        "\xEF\xBB\xBF" "0 0 0\n1 2 3\n4 5 6\n",
        "; a comment\n0 0 0 ; after a point\n# another\n\n1 2 3\n\t4 5 6\t\n# last\n",
        "4\n0 0\n1 1\n2 2\n3 3\n",
        "SLOPES 0.5 1\n0 0 0\n1 1 1\n2 2 2\n3 3 3\n",
        "PART a\n0 0\n1 1\nPART b CLOSED\n2 2\n3 3\n4 4\nPART c\n5 5\n6 6\n",
        "0 0 0 0.25 -0.5 0 1\n1 1 1 0 0 0 0\n2 2 2 1 1 1 1\n3 3 3 -1 -1 -1 -1\n",
        "0 0 0\n1 1 1\n2 2 2\n0 0 0\n",
        "0 0\n1 1\n2 2\n3 3\n\x1A\n\n",
        "0 0\n1 1\n2 2\n\x1A",
        "0 0\n1 1\n2 2 2\n3 3 3",
        "0 0\n1 1\n",
        "0 0 0\n",
        "0 0 0",
        "",
        "\n\n\n\n",
    };
    for (const std::string& text : texts)
        require_same_readings(text);
    require_same_readings("0 0 0\n", 1);
    require_same_readings(points_with(400, 0, ""));
    require_same_readings(points_with(400, 0, "", "\r\n"));
}

TEST_CASE("a file read in halves gives the first problem read in order gives wherever it stands", "[formats][dat][halves]")
{
    const std::vector<std::string> faults{
        "1 one 2",           "1 2 3 4",      "7",           "nan 1 1",         "1 1 1e999",
        "1 2000000000 1",    "0 0 0 1.5 0 0 0", "0 0 0 0 0 0 -1.5", "PART",      "PART a SHUT",
        "PART tail",         "SLOPES 0.5 1", "SLOPES 2 1",  std::string(5000, ' '), std::string("1 \0 2", 5),
        "\xEF\xBB\xBF" "1 1", "\x1A",        "1 1\x1A",     "PART x CLOSED",   "; only a comment",
    };
    const int lines = 41;
    for (const std::string& fault : faults)
        for (int line = 1; line <= lines; ++line) {
            require_same_readings(points_with(lines, line, fault));
            require_same_readings(points_with(lines, line, fault, "\r\n"));
            // Two problems, one in each half: the first one is said.
            require_same_readings(points_with(lines, line, fault) + points_with(lines, 3, "1 bad 2"));
        }
}

TEST_CASE("a count line or a file of one line read in halves", "[formats][dat][halves]")
{
    require_same_readings("40\n" + points_with(40, 0, ""));
    require_same_readings("41\n" + points_with(40, 0, ""));
    require_same_readings(points_with(1, 0, ""));
    require_same_readings(points_with(1, 0, ""), 1);
    require_same_readings("1 2 3");
    require_same_readings("1 2 3", 1);
}

TEST_CASE("more than a million points read in halves are refused on the same line", "[formats][dat][halves]")
{
    std::string text;
    text.reserve((max_dat_points + 1) * 4);
    for (std::size_t i = 0; i <= max_dat_points; ++i)
        text += "1 1\n";
    const Expected<DatFile> file = parse_dat(text, "key1.dat", 2, DatReading::in_halves);
    REQUIRE_FALSE(file.has_value());
    REQUIRE(file.error().to_string() == "key1.dat:1000001: more than 1000000 points; expected at most that many");
    text.resize(text.size() - 4);
    const Expected<DatFile> all = parse_dat(text, "key1.dat", 2, DatReading::in_halves);
    REQUIRE(all.has_value());
    REQUIRE(all->point_count() == max_dat_points);
    REQUIRE(all->parts[0].points.back().line == 1000000);
}
