#include "apcs/geometry/pixel_point.h"

#include <catch2/catch.hpp>

using namespace apcs;

TEST_CASE("a pixel rectangle contains its left and top edges but not its right and bottom ones",
          "[geometry][pixel]")
{
    constexpr PixelRect rect{10, 20, 30, 25};
    STATIC_REQUIRE(rect.width() == 20);
    STATIC_REQUIRE(rect.height() == 5);
    STATIC_REQUIRE(rect.contains({10, 20}));
    STATIC_REQUIRE(rect.contains({29, 24}));
    STATIC_REQUIRE_FALSE(rect.contains({30, 24}));
    STATIC_REQUIRE_FALSE(rect.contains({29, 25}));
    STATIC_REQUIRE_FALSE(rect.contains({9, 20}));
    STATIC_REQUIRE_FALSE(rect.contains({10, 19}));
}

TEST_CASE("an empty pixel rectangle contains nothing", "[geometry][pixel]")
{
    constexpr PixelRect empty{5, 5, 5, 5};
    STATIC_REQUIRE(empty.width() == 0);
    STATIC_REQUIRE_FALSE(empty.contains({5, 5}));
}

TEST_CASE("pixel points compare by both coordinates", "[geometry][pixel]")
{
    STATIC_REQUIRE(PixelPoint{3, 4} == PixelPoint{3, 4});
    STATIC_REQUIRE_FALSE(PixelPoint{3, 4} == PixelPoint{4, 3});
}
