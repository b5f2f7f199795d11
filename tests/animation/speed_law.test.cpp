#include "apcs/animation/speed_law.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace apcs;

TEST_CASE("every speed law starts at 0, ends at 1 and never goes back", "[animation][speed]")
{
    for (const SpeedLaw law : {SpeedLaw::linear, SpeedLaw::ease_in, SpeedLaw::ease_out, SpeedLaw::ease_in_out,
                               SpeedLaw::sqrt, SpeedLaw::square}) {
        CAPTURE(speed_law_name(law));
        REQUIRE(distance_fraction(law, 0.0) == Approx(0.0).margin(1e-15));
        REQUIRE(distance_fraction(law, 1.0) == Approx(1.0));
        double previous = 0.0;
        for (int i = 1; i <= 1000; ++i) {
            const double value = distance_fraction(law, i / 1000.0);
            REQUIRE(value >= previous);
            REQUIRE(value <= 1.0 + 1e-15);
            previous = value;
        }
        REQUIRE(speed_law_from_name(speed_law_name(law)) == law);
    }
}

TEST_CASE("speed laws worked by hand at t = 1/4", "[animation][speed]")
{
    REQUIRE(distance_fraction(SpeedLaw::sqrt, 0.25) == Approx(0.5));
    REQUIRE(distance_fraction(SpeedLaw::square, 0.25) == Approx(0.0625));
    REQUIRE(distance_fraction(SpeedLaw::ease_out, 0.25) == Approx(std::sin(M_PI / 8)));
    REQUIRE(distance_fraction(SpeedLaw::ease_in, 0.25) == Approx(1 - std::cos(M_PI / 8)));
    REQUIRE(distance_fraction(SpeedLaw::ease_in_out, 0.25) == Approx((1 - std::cos(M_PI / 4)) / 2));
    REQUIRE_FALSE(speed_law_from_name("bouncy").has_value());
}

TEST_CASE("the acceleration law blends linear and the cosine warp by |a|", "[animation][speed]")
{
    REQUIRE(acceleration_distance_fraction(0.3, 0.0) == Approx(0.3));
    REQUIRE(acceleration_distance_fraction(0.5, -1.0) == Approx(std::sin(M_PI / 4)));
    REQUIRE(acceleration_distance_fraction(0.5, 1.0) == Approx(1 - std::cos(M_PI / 4)));
    REQUIRE(acceleration_distance_fraction(0.5, 0.4) == Approx(0.6 * 0.5 + 0.4 * (1 - std::cos(M_PI / 4))));
    REQUIRE(acceleration_distance_fraction(0.5, 7.0) == acceleration_distance_fraction(0.5, 1.0));
}
