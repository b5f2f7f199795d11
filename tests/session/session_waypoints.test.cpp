// The waypoint editor and undo in a whole session: what reaches the path file.
#include "apcs/formats/dat_file.h"
#include "apcs/session/session.h"
#include "apcs/session/session_files.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace apcs;
using apcs::test::type;

namespace {

void press(Session& session, const std::string& keys)
{
    for (const char c : keys)
        session.handle(c == '\n' ? KeyEvent::of(Key::enter) : KeyEvent::typed(static_cast<char32_t>(c)));
}

// Two keys of one graphic point each side: the first point goes (0,0,0) → (0,0,10).
MemoryFiles two_point_files(const std::string& path_text)
{
    MemoryFiles files;
    files.files["key1.dat"] = "0 0 0\n0 6 0\n";
    files.files["key2.dat"] = "0 0 10\n0 6 10\n";
    files.files["two.dat"] = path_text;
    return files;
}

// KEY1, KEY2, the view (THETA, PHI), the path file, the slopes: the 8/2 choice.
void open_path(Session& session, const std::string& view)
{
    type(session, "");
    type(session, "");
    type(session, view);
    type(session, "two.dat");
    type(session, "");
    REQUIRE(session.leaf_name() == "control_choice");
}

std::vector<DatPoint> points_of(const std::string& text)
{
    const Expected<DatFile> file = parse_dat(text, "two.dat");
    REQUIRE(file);
    return file->parts.at(0).points;
}

} // namespace

TEST_CASE("a waypoint inserted and moved up 4 steps is written to the path file where the view's up says",
          "[session][waypoints]")
{
    MemoryFiles files = two_point_files("; the thesis' ani1.dat, two points\n0 0 0\n0 0 10\n");
    Session session({}, files);
    open_path(session, "30 40 200");
    press(session, "WI8888\n");
    REQUIRE(session.leaf_name() == "control_choice");
    press(session, "8\n\n\n\nN");
    REQUIRE(session.leaf_name() == "ask_next_path");
    const std::string written = files.files["two.dat"];
    REQUIRE(written.starts_with("; the thesis' ani1.dat, two points\n"));
    const std::vector<DatPoint> points = points_of(written);
    REQUIRE(points.size() == 3);
    // The view shows both keys: x 0 to 0, y 0 to 6, z 0 to 10; a step is 1 % of that box's diagonal.
    const double step = std::sqrt(36.0 + 100.0) / 100.0;
    // Up the screen at THETA 30, PHI 40: (-cos 30 cos 40, -sin 30 cos 40, sin 40).
    const double to_radians = std::acos(-1.0) / 180.0;
    const double theta = 30 * to_radians;
    const double phi = 40 * to_radians;
    const Vec3 up{-std::cos(theta) * std::cos(phi), -std::sin(theta) * std::cos(phi), std::sin(phi)};
    const Vec3 expected = Vec3{0, 0, 5} + 4 * step * up;
    REQUIRE(points[1].position.x == Approx(expected.x).margin(1e-12));
    REQUIRE(points[1].position.y == Approx(expected.y).margin(1e-12));
    REQUIRE(points[1].position.z == Approx(expected.z).margin(1e-12));
    REQUIRE(points[1].staff == StaffValues{});
    REQUIRE(points[0].position == Vec3{0, 0, 0});
    REQUIRE(points[2].position == Vec3{0, 0, 10});
}

TEST_CASE("undoing every change and accepting writes the path file as it was", "[session][waypoints]")
{
    const std::string original = "; way: comments stay\n0 0 0 0 0 0 0\n; the bend\n0 3 5 0.5 0 0 0.25 ; kept\n"
                                 "0 0 10 0 0 0 0\n";
    MemoryFiles files = two_point_files(original);
    Session session({}, files);
    open_path(session, "0 90 100");
    // Waypoints: insert, move twice, delete the bend; then the staff: two steps and a typed value.
    press(session, "WI88]D\n866\n=-0.4\n");
    REQUIRE(points_of(files.files["two.dat"]).size() == 3);
    for (int change = 0; change < 7; ++change)
        press(session, "U");
    REQUIRE(session.leaf_name() == "control_choice");
    press(session, "U");
    REQUIRE(session.screen().picture.text.size() > 0);
    bool nothing_left = false;
    for (const TextLine& line : session.screen().picture.text)
        nothing_left = nothing_left || line.text == "Nothing to undo: the path is as it was opened";
    REQUIRE(nothing_left);
    // Through the staff of one point and out without a change: the file comes back as it was read,
    // with the slopes it was shaped with (1 1) before its first point (SPEC §2.1).
    press(session, "2" "6\n\n");
    press(session, "\n\n\n\n");
    REQUIRE(session.leaf_name() == "ask_next_path");
    std::string with_slopes = original;
    with_slopes.insert(with_slopes.find('\n') + 1, "SLOPES 1 1\n");
    REQUIRE(files.files["two.dat"] == with_slopes);
}
