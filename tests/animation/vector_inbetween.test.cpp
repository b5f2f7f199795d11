#include "apcs/animation/vector_inbetween.h"

#include <catch2/catch.hpp>

using namespace apcs;

namespace {
const Vec3 p1{0, 0, 0};
const Vec3 p2{2, 0, 0};
const Vec3 p3{2, 4, 0};
const std::vector<Vec3> three{p1, p2, p3};
} // namespace

TEST_CASE("each padding from 3 to 5 points, worked by hand", "[animation][inbetween]")
{
    // n − m = 2; s_i = ⌈i·3/2⌉ for i = 1, 2: s = 2, 3.
    REQUIRE(pad_points(three, 5, Padding::start) == std::vector<Vec3>{p1, p1, p1, p2, p3});
    REQUIRE(pad_points(three, 5, Padding::end) == std::vector<Vec3>{p1, p2, p3, p3, p3});
    REQUIRE(pad_points(three, 5, Padding::middle) == std::vector<Vec3>{p1, p2, p2, p3, p3});
    // The midpoint of segment 2 (P2, P3) is (2, 2, 0); at s = m = 3 the midpoint is P3 itself.
    REQUIRE(pad_points(three, 5, Padding::midpoint) == std::vector<Vec3>{p1, p2, {2, 2, 0}, p3, p3});
    // Algorithm 2: RT = 4 div 2 = 2, RS = 0: one point in the middle of each segment.
    REQUIRE(pad_points(three, 5, Padding::apcs) == std::vector<Vec3>{p1, {1, 0, 0}, p2, {2, 2, 0}, p3});
}

TEST_CASE("middle padding from 4 to 6 points chooses s = 2 and 4", "[animation][inbetween]")
{
    const Vec3 p4{0, 4, 0};
    const std::vector<Vec3> four{p1, p2, p3, p4};
    // s_i = ⌈i·4/2⌉ = 2, 4.
    REQUIRE(pad_points(four, 6, Padding::middle) == std::vector<Vec3>{p1, p2, p2, p3, p4, p4});
    REQUIRE(pad_points(four, 6, Padding::midpoint) == std::vector<Vec3>{p1, p2, {2, 2, 0}, p3, p4, p4});
}

TEST_CASE("padding never shortens and reaches the count for any sizes", "[animation][inbetween]")
{
    for (const Padding padding : {Padding::apcs, Padding::start, Padding::end, Padding::middle, Padding::midpoint})
        for (std::size_t target = 3; target < 20; ++target)
            REQUIRE(pad_points(three, target, padding).size() == target);
    REQUIRE(pad_points(three, 2, Padding::middle) == three);
}

TEST_CASE("interpolated frames run from Gb to Ge by the law", "[animation][inbetween]")
{
    const std::vector<Vec3> begin{{0, 0, 0}, {1, 0, 0}};
    const std::vector<Vec3> end{{4, 0, 0}, {1, 8, 0}};
    const FrameSequence frames = interpolate_frames(begin, end, 4, SpeedLaw::square);
    REQUIRE(frames.frame_count() == 5);
    REQUIRE(frames.frame(0)[0] == begin[0]);
    REQUIRE(frames.frame(4)[1] == end[1]);
    // t = 1/2, f = 1/4: (1, 0, 0) and (1, 2, 0).
    REQUIRE(frames.frame(2)[0] == Vec3{1, 0, 0});
    REQUIRE(frames.frame(2)[1] == Vec3{1, 2, 0});
    const FrameSequence rooted = interpolate_frames(begin, end, 4, SpeedLaw::sqrt);
    REQUIRE(rooted.frame(1)[0].x == Approx(2.0)); // √(1/4) = 1/2
}

TEST_CASE("padding names", "[animation][inbetween]")
{
    REQUIRE(padding_from_name("midpoint") == Padding::midpoint);
    REQUIRE_FALSE(padding_from_name("centre").has_value());
}
