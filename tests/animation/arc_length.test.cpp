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

// Composite Simpson over [0, u_end] from derivative_at, every sum added in order.
double simpson(const HermiteSegment& segment, double u_end, int intervals)
{
    const double step = u_end / intervals;
    double sum = length(segment.derivative_at(0.0)) + length(segment.derivative_at(u_end));
    for (int i = 1; i < intervals; ++i)
        sum += (i % 2 == 1 ? 4.0 : 2.0) * length(segment.derivative_at(step * i));
    return sum * step / 3.0;
}

// The arc length as the table was first written: composite Simpson from derivative_at, the interval
// count doubling from 32 until two sums agree to 1e-10 (at most 8192); and that count.
std::pair<double, int> simpson_reference_and_count(const HermiteSegment& segment)
{
    int intervals = 32;
    double sum = simpson(segment, 1.0, intervals);
    while (intervals < 8192) {
        intervals *= 2;
        const double finer = simpson(segment, 1.0, intervals);
        const bool converged = std::abs(finer - sum) <= 1e-10 * finer;
        sum = finer;
        if (converged)
            break;
    }
    return {sum, intervals};
}

double simpson_reference(const HermiteSegment& segment) { return simpson_reference_and_count(segment).first; }

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

TEST_CASE("arc lengths are Simpson's from derivative_at to the bit at every scale and count, and their counts too",
          "[animation][arc-length]")
{
    // Whether two counts agree is decided on estimates unless they are too near the bound to tell:
    // segments of lengths from 1e-250 (speeds that underflow) to 1e150, of no length, straight, and
    // bent by every tension, so that counts from 32 to 8192 and sums near the bound all occur.
    std::vector<HermiteSegment> segments;
    for (const double scale : {1e-250, 1e-160, 1e-9, 1.0, 3e7, 1e150}) {
        ControlPoints points;
        for (int k = 0; k < 300; ++k)
            points.push_back({Vec3{std::sin(k * 0.9) * 3.0, k * 0.01 * std::cos(k * 0.31), std::cos(k * 1.7) * 4.0} * scale,
                              {std::sin(k * 0.37), std::cos(k * 0.53), std::sin(k * 0.71), 0.0}});
        points[100].position = points[101].position; // a segment of no length
        const std::vector<HermiteSegment> made = kb_segments(points, {});
        segments.insert(segments.end(), made.begin(), made.end());
    }
    segments.push_back({{0, 0, 0}, {3, 4, 0}, {3, 4, 0}, {3, 4, 0}}); // straight: every speed 5
    segments.push_back({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}});
    segments.push_back({{0, 0, 0}, {1, 0, 0}, {40, 0, 0}, {40, 0, 0}}); // a loop back and forth: a cusp
    CurveArcLengths lengths;
    lengths.measure(segments);
    double running = 0.0;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        CAPTURE(s);
        const auto [length, intervals] = simpson_reference_and_count(segments[s]);
        REQUIRE(lengths.length_at(segments, {s, 0.0}) == running);
        // length_at sums with the segment's count: the same count gives the same bits.
        REQUIRE(lengths.length_at(segments, {s, 0.375}) == running + simpson(segments[s], 0.375, intervals));
        running += length;
        REQUIRE(lengths.length_to_segment_start(s + 1) == running);
    }
}

TEST_CASE("halfway_parameter halves a segment's arc length as the Simpson table does, at a bounded cost",
          "[animation][arc-length]")
{
    const std::vector<HermiteSegment> segments{
        {{0, 0, 0}, {10, 0, 0}, {10, 0, 0}, {10, 0, 0}},        // straight, even speed: 0.5
        {{0, 0, 0}, {10, 0, 0}, {30, 0, 0}, {1, 0, 0}},         // straight, fast then slow
        {{0, 0, 0}, {0, 6, 3}, {9, -12, 10}, {0, 0, 5}},        // N to L's bend
        {{1, 2, 3}, {1, 2, 3.000001}, {0, 0, 0.000001}, {0, 0, 0.000001}}, // a millionth long
        {{0, 0, 0}, {4, 0, 0}, {0, 20, 0}, {0, -20, 0}},        // a loop out and back
    };
    for (const HermiteSegment& segment : segments) {
        CAPTURE(segment.start.x, segment.end.z, segment.start_tangent.x);
        const ArcLengthTable table(std::span(&segment, 1));
        const double u = halfway_parameter(segment);
        REQUIRE(u > 0.0);
        REQUIRE(u < 1.0);
        REQUIRE(table.length_at({0, u}) == Approx(table.total_length() / 2.0).epsilon(1e-9));
    }
    REQUIRE(halfway_parameter({{0, 0, 0}, {10, 0, 0}, {10, 0, 0}, {10, 0, 0}}) == Approx(0.5).epsilon(1e-12));
    // A segment of no length (a point inserted on a point): its middle parameter.
    REQUIRE(halfway_parameter({{1, 1, 1}, {1, 1, 1}, {0, 0, 0}, {0, 0, 0}}) == 0.5);
}
