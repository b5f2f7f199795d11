#include "apcs/animation/control_region.h"
#include "support/memory_mappings.h"

#include <catch2/catch.hpp>

#include <string>

using namespace apcs;

namespace {

ControlPoints five_points()
{
    ControlPoints points;
    for (int k = 0; k < 5; ++k)
        points.push_back({{0, static_cast<double>(k), 0}, {}});
    return points;
}

} // namespace

TEST_CASE("a local region's last point keeps its acceleration: it starts the span after the region",
          "[animation][region]")
{
    ControlPoints points = five_points();
    apply_staff_to_region(points, {1, 3}, {0.5, -0.25, 0.75, 0.4});
    for (std::size_t k = 0; k < points.size(); ++k) {
        CAPTURE(k);
        const bool inside = k >= 1 && k <= 3;
        REQUIRE(points[k].staff.tension == (inside ? 0.5 : 0.0));
        REQUIRE(points[k].staff.continuity == (inside ? -0.25 : 0.0));
        REQUIRE(points[k].staff.bias == (inside ? 0.75 : 0.0));
        REQUIRE(points[k].staff.acceleration == (k == 1 || k == 2 ? 0.4 : 0.0));
    }
}

TEST_CASE("global control gives every point, the last too, the staff's acceleration", "[animation][region]")
{
    ControlPoints points = five_points();
    const ControlRegion whole = ControlRegion::whole(points);
    REQUIRE(whole.first == 0);
    REQUIRE(whole.last == 4);
    REQUIRE(whole.is_whole(points));
    apply_staff_to_region(points, whole, {0, 0, 0, -0.6});
    for (const ControlPoint& point : points)
        REQUIRE(point.staff.acceleration == -0.6);
}

TEST_CASE("staff values reaching a region are clamped to -1 and +1, and a region past the path stops at its end",
          "[animation][region]")
{
    ControlPoints points = five_points();
    apply_staff_to_region(points, {3, 9}, {3.0, -7.0, 1.5, -2.0});
    REQUIRE(points[4].staff == StaffValues{1.0, -1.0, 1.0, -1.0});
    REQUIRE(points[3].staff.acceleration == -1.0);
    REQUIRE(points[2].staff == StaffValues{});
}

TEST_CASE("a staff line names its value and the next line", "[animation][region]")
{
    StaffValues staff{0.1, 0.2, 0.3, 0.4};
    REQUIRE(staff[StaffLine::tension] == 0.1);
    REQUIRE(staff[StaffLine::continuity] == 0.2);
    REQUIRE(staff[StaffLine::bias] == 0.3);
    REQUIRE(staff[StaffLine::acceleration] == 0.4);
    staff[StaffLine::bias] = -0.5;
    REQUIRE(staff.bias == -0.5);
    REQUIRE(staff_line_name(StaffLine::continuity) == "CONTINUITY");
    REQUIRE(next_staff_line(StaffLine::bias) == StaffLine::acceleration);
    REQUIRE(is_last_staff_line(StaffLine::acceleration));
    REQUIRE_FALSE(is_last_staff_line(StaffLine::tension));
}

TEST_CASE("a region of 200000 control points, done in two halves, gives back its runs as they were",
          "[animation][region]")
{
    ControlPoints points(200000);
    for (std::size_t k = 0; k < points.size(); ++k)
        points[k].staff = {k < 100000 ? 0.25 : 0.5, 0, 0, (k / 7000) % 3 == 0 ? -0.5 : 0.0};
    const ControlRegion region{3, 199990};
    const std::vector<StaffRun> expected = staff_runs(points, region);
    REQUIRE(expected.size() > 20);
    const std::vector<StaffRun> before = apply_staff_to_region(points, region, {0.1, 0.2, 0.3, 0.4});
    CHECK(before == expected);
    CHECK(points[2].staff == StaffValues{0.25, 0, 0, -0.5});
    CHECK(points[150000].staff == StaffValues{0.1, 0.2, 0.3, 0.4});
    CHECK(points[199990].staff.tension == 0.1);
    CHECK(points[199990].staff.acceleration == 0.0); // the region's last point starts the span after it
    restore_staff_runs(points, region, before);
    CHECK(staff_runs(points, region) == expected);
}

// A global key passes over every control point; after a person's wait, on a virtual machine, that
// pass over 56 MB in 4 KB pages took 35-80 ms instead of 8 (PERFORMANCE.md 9i).
TEST_CASE("a path of 10^6 control points is held in memory advised for 2 MB pages", "[animation][region]")
{
    ControlPoints points(1'000'000);
    test::check_advised_for_huge_pages(&points[500'000]);
}
