#include "apcs/animation/arc_length.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/sampled_curve.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace apcs;

TEST_CASE("the arc length of a straight segment is its chord", "[animation][arc-length]")
{
    const HermiteSegment segment{{0, 0, 0}, {3, 4, 0}, {3, 4, 0}, {3, 4, 0}};
    const ArcLengthTable table(std::span(&segment, 1));
    REQUIRE(table.total_length() == Approx(5.0).epsilon(1e-12));
    const CurveParameter half = table.parameter_at(2.5);
    REQUIRE(half.u == Approx(0.5).margin(1e-9));
}

TEST_CASE("Simpson's arc length agrees with a fine chord sum", "[animation][arc-length]")
{
    ControlPoints points;
    for (const Vec3& position : {Vec3{0, 0, 0}, Vec3{2, 5, 1}, Vec3{6, -1, 0}, Vec3{9, 4, 3}})
        points.push_back({position, {0.2, -0.3, 0.4, 0}});
    const auto segments = kb_segments(points, {});
    const ArcLengthTable table(segments);
    const double fine = sample_curve(segments, 100000).total_length();
    REQUIRE(table.total_length() == Approx(fine).epsilon(1e-7));
    REQUIRE(table.length_to_segment_start(segments.size()) == table.total_length());
}

TEST_CASE("parameter_at inverts length_at and clamps outside the curve", "[animation][arc-length]")
{
    const HermiteSegment segments[] = {{{0, 0, 0}, {4, 4, 0}, {8, 0, 0}, {0, 8, 0}},
                                       {{4, 4, 0}, {9, 1, 2}, {0, 8, 0}, {5, -3, 2}}};
    const ArcLengthTable table(segments);
    const double length = table.total_length();
    for (double fraction : {0.0, 0.1, 0.45, 0.5, 0.77, 1.0}) {
        const CurveParameter parameter = table.parameter_at(fraction * length);
        REQUIRE(std::abs(table.length_at(parameter) - fraction * length) <= 1e-9 * length);
    }
    REQUIRE(table.point_at(table.parameter_at(-5)) == Vec3{0, 0, 0});
    REQUIRE(distance(table.point_at(table.parameter_at(length * 2)), Vec3{9, 1, 2}) < 1e-9);
}

namespace {

// The arc length as the table was first written: composite Simpson from derivative_at, the interval
// count doubling from 32 until two sums agree to 1e-10 (at most 8192).
double simpson_reference(const HermiteSegment& segment)
{
    const auto simpson = [&](int intervals) {
        const double step = 1.0 / intervals;
        double sum = length(segment.derivative_at(0.0)) + length(segment.derivative_at(1.0));
        for (int i = 1; i < intervals; ++i)
            sum += (i % 2 == 1 ? 4.0 : 2.0) * length(segment.derivative_at(step * i));
        return sum * step / 3.0;
    };
    int intervals = 32;
    double sum = simpson(intervals);
    while (intervals < 8192) {
        intervals *= 2;
        const double finer = simpson(intervals);
        const bool converged = std::abs(finer - sum) <= 1e-10 * finer;
        sum = finer;
        if (converged)
            break;
    }
    return sum;
}

} // namespace

TEST_CASE("each segment's arc length, from tabulated speeds, is Simpson's from derivative_at to the bit",
          "[animation][arc-length]")
{
    ControlPoints points;
    for (int k = 0; k < 400; ++k) // flat, bent and cusped segments (tension -1 overshoots)
        points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.01, std::cos(k * 1.7) * 4.0},
                          {std::sin(k * 0.3), std::cos(k * 0.5), 0.0, 0.0}});
    const std::vector<HermiteSegment> segments = kb_segments(points, {});
    const ArcLengthTable table(segments);
    double running = 0.0;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        CAPTURE(s);
        running += simpson_reference(segments[s]);
        REQUIRE(table.length_to_segment_start(s + 1) == running);
    }
    REQUIRE(table.total_length() == running);
}
