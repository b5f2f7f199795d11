#include "apcs/geometry/bounding_box.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace apcs;

TEST_CASE("a bounding box is empty until a point is added", "[geometry][bounding-box]")
{
    BoundingBox box;
    REQUIRE(box.empty());
    box.add(Vec3{1, -2, 3});
    REQUIRE_FALSE(box.empty());
    REQUIRE(box.low() == Vec3{1, -2, 3});
    REQUIRE(box.high() == Vec3{1, -2, 3});
    REQUIRE(box.half_diagonal() == 0.0);
}

TEST_CASE("a bounding box spans its points axis by axis, with centre and half diagonal", "[geometry][bounding-box]")
{
    BoundingBox box;
    const std::array<Vec3, 3> points{{{1, 5, -1}, {-3, 2, 4}, {2, -1, 0}}};
    box.add(points);
    REQUIRE(box.low() == Vec3{-3, -1, -1});
    REQUIRE(box.high() == Vec3{2, 5, 4});
    REQUIRE(box.centre() == Vec3{-0.5, 2, 1.5});
    // The diagonal (5, 6, 5) is sqrt(86) long.
    REQUIRE(box.half_diagonal() == Approx(std::sqrt(86.0) / 2.0));
}
