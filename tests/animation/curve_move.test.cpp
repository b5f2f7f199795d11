#include "apcs/animation/curve_move.h"
#include "apcs/animation/sampled_curve.h"

#include <catch2/catch.hpp>

using namespace apcs;

TEST_CASE("a segment's move is the furthest distance of a new sample from the old samples' polyline",
          "[animation][move]")
{
    const std::vector<HermiteBasis> basis = hermite_basis_table(32);
    // A straight segment from (0,0,0) to (0,0,10) with tangents along it.
    const HermiteSegment straight{{0, 0, 0}, {0, 0, 10}, {0, 0, 10}, {0, 0, 10}};
    SECTION("an unchanged segment did not move")
    {
        REQUIRE(furthest_sample_move(straight, straight, basis).distance == 0.0);
    }
    SECTION("shorter tangents along the line slide the samples along it: no move")
    {
        const HermiteSegment slid{{0, 0, 0}, {0, 0, 10}, {0, 0, 5}, {0, 0, 5}};
        REQUIRE(furthest_sample_move(straight, slid, basis).distance == Approx(0.0).margin(1e-12));
    }
    SECTION("an end tangent turned across the line bends the segment: f4 = u^3 - u^2, largest 4/27 at u = 2/3")
    {
        const HermiteSegment bent{{0, 0, 0}, {0, 0, 10}, {0, 0, 10}, {0, 1, 10}};
        // Sample j = 21 (u = 0.65625): |f4| = 0.148041; the old line is straight, so the nearest
        // point is straight across.
        const SampleMove move = furthest_sample_move(straight, bent, basis);
        REQUIRE(move.distance == Approx(0.148041).epsilon(1e-5));
        REQUIRE(move.after.y == Approx(-0.148041).epsilon(1e-5));
        REQUIRE(move.before.y == Approx(0.0).margin(1e-12));
    }
    SECTION("a segment whose samples moved no more than at_least is not searched")
    {
        const HermiteSegment bent{{0, 0, 0}, {0, 0, 10}, {0, 0, 10}, {0, 1, 10}};
        REQUIRE(furthest_sample_move(straight, bent, basis, 0.2).distance == 0.0);
    }
}
