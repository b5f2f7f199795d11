#include "apcs/geometry/vec3.h"

#include <catch2/catch.hpp>

using namespace apcs;

TEST_CASE("vectors add, subtract, scale and negate component by component", "[geometry][vec3]")
{
    constexpr Vec3 a{1, 2, 3};
    constexpr Vec3 b{4, -5, 0.5};
    STATIC_REQUIRE(a + b == Vec3{5, -3, 3.5});
    STATIC_REQUIRE(a - b == Vec3{-3, 7, 2.5});
    STATIC_REQUIRE(a * 2.0 == Vec3{2, 4, 6});
    STATIC_REQUIRE(2.0 * a == a * 2.0);
    STATIC_REQUIRE(-a == Vec3{-1, -2, -3});
    Vec3 c = a;
    c += b;
    c -= a;
    c *= 2.0;
    REQUIRE(c == Vec3{8, -10, 1});
}

TEST_CASE("dot product, length and distance worked by hand", "[geometry][vec3]")
{
    STATIC_REQUIRE(dot(Vec3{1, 2, 3}, Vec3{4, -5, 6}) == 12.0);
    REQUIRE(length(Vec3{2, 3, 6}) == 7.0);
    REQUIRE(distance(Vec3{1, 1, 1}, Vec3{3, 4, 7}) == 7.0);
    REQUIRE(length(Vec3{}) == 0.0);
}

TEST_CASE("lerp gives `from` at 0, `to` at 1 and the midpoint at 1/2", "[geometry][vec3]")
{
    constexpr Vec3 from{0, 2, -4};
    constexpr Vec3 to{4, 6, 4};
    STATIC_REQUIRE(lerp(from, to, 0.0) == from);
    STATIC_REQUIRE(lerp(from, to, 1.0) == to);
    STATIC_REQUIRE(lerp(from, to, 0.5) == Vec3{2, 4, 0});
}
