#include "apcs/animation/waypoint_change.h"

#include <catch2/catch.hpp>

using namespace apcs;
using Kind = WaypointChange::Kind;

namespace {

ControlPoints three_points()
{
    return {{{0, 0, 0}, {0.1, 0, 0, 0}}, {{0, 3, 5}, {0.5, -0.2, 0.3, 0.25}}, {{0, 0, 10}, {}}};
}

void require_same(const ControlPoints& actual, const ControlPoints& expected)
{
    REQUIRE(actual.size() == expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        REQUIRE(actual[k].position == expected[k].position);
        REQUIRE(actual[k].staff == expected[k].staff);
    }
}

} // namespace

TEST_CASE("an inserted point has no origin in the file, and reverting takes it out", "[animation][waypoints]")
{
    ControlPoints points = three_points();
    std::vector<std::size_t> origins{0, 1, 2};
    const WaypointChange insert{Kind::insert, 1, {{1, 2, 3}, {0.4, 0, 0, 0}}, 7, {}};
    apply_change(points, origins, insert);
    REQUIRE(points.size() == 4);
    REQUIRE(points[1].position == Vec3{1, 2, 3});
    REQUIRE(points[1].staff.tension == 0.4);
    REQUIRE(origins == std::vector<std::size_t>{0, new_point, 1, 2});
    revert_change(points, origins, insert);
    require_same(points, three_points());
    REQUIRE(origins == std::vector<std::size_t>{0, 1, 2});
}

TEST_CASE("a removed point comes back where it was, with its values and its origin", "[animation][waypoints]")
{
    ControlPoints points = three_points();
    std::vector<std::size_t> origins{0, 1, 2};
    const WaypointChange remove{Kind::remove, 1, three_points()[1], 1, {}};
    apply_change(points, origins, remove);
    REQUIRE(points.size() == 2);
    REQUIRE(points[1].position == Vec3{0, 0, 10});
    REQUIRE(origins == std::vector<std::size_t>{0, 2});
    revert_change(points, origins, remove);
    require_same(points, three_points());
    REQUIRE(origins == std::vector<std::size_t>{0, 1, 2});
}

TEST_CASE("a move shifts one point by its offset and reverting shifts it back", "[animation][waypoints]")
{
    ControlPoints points = three_points();
    std::vector<std::size_t> origins{0, 1, 2};
    const WaypointChange move{Kind::move, 1, {}, new_point, {0.5, -1, 2}};
    apply_change(points, origins, move);
    REQUIRE(points[1].position == Vec3{0.5, 2, 7});
    REQUIRE(points[1].staff == three_points()[1].staff);
    REQUIRE(points[0].position == Vec3{0, 0, 0});
    REQUIRE(origins == std::vector<std::size_t>{0, 1, 2});
    revert_change(points, origins, move);
    require_same(points, three_points());
}

TEST_CASE("changes reverted newest first give back the points they started from", "[animation][waypoints]")
{
    ControlPoints points = three_points();
    std::vector<std::size_t> origins{0, 1, 2};
    const std::vector<WaypointChange> changes{
        {Kind::insert, 2, {{0, 1, 8}, {}}, new_point, {}},
        {Kind::move, 2, {}, new_point, {0, 0, 0.5}},
        {Kind::remove, 1, three_points()[1], 1, {}},
        {Kind::move, 1, {}, new_point, {1, 0, 0}},
    };
    for (const WaypointChange& change : changes)
        apply_change(points, origins, change);
    REQUIRE(points.size() == 3);
    REQUIRE(points[1].position == Vec3{1, 1, 8.5});
    REQUIRE(origins == std::vector<std::size_t>{0, new_point, 2});
    for (auto change = changes.rbegin(); change != changes.rend(); ++change)
        revert_change(points, origins, *change);
    require_same(points, three_points());
    REQUIRE(origins == std::vector<std::size_t>{0, 1, 2});
}
