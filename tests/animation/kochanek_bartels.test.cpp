#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/sampled_curve.h"
#include "support/memory_mappings.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

using namespace apcs;

namespace {

ControlPoints points_with(std::initializer_list<Vec3> positions, StaffValues staff = {})
{
    ControlPoints points;
    for (const Vec3& position : positions)
        points.push_back({position, staff});
    return points;
}

void require_near(const Vec3& actual, const Vec3& expected, double tolerance = 1e-12)
{
    CAPTURE(actual.x, actual.y, actual.z, expected.x, expected.y, expected.z);
    REQUIRE(distance(actual, expected) <= tolerance);
}

double cross_z(const Vec3& a, const Vec3& b) { return a.x * b.y - a.y * b.x; }

const std::initializer_list<Vec3> zigzag = {{0, 0, 0}, {2, 3, 0}, {5, 1, 0}, {7, 4, 0}, {10, 2, 0}};

} // namespace

TEST_CASE("the Hermite basis is 1 and 0 at the ends and sums to one", "[animation][hermite]")
{
    for (double u : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const HermiteBasis basis = hermite_basis(u);
        REQUIRE(basis.f1 + basis.f2 == Approx(1.0));
    }
    REQUIRE(hermite_basis(0.0).f1 == 1.0);
    REQUIRE(hermite_basis(1.0).f2 == 1.0);
    // F3(u) = u³−2u²+u and F4(u) = u³−u² at u = 0.5: 0.125 and −0.125.
    REQUIRE(hermite_basis(0.5).f3 == Approx(0.125));
    REQUIRE(hermite_basis(0.5).f4 == Approx(-0.125));
}

TEST_CASE("zero tension, continuity and bias give the Catmull-Rom midpoint (-P0+9P1+9P2-P3)/16", "[animation][kb]")
{
    const ControlPoints points = points_with({{0, 0, 0}, {1, 2, 1}, {4, 3, -1}, {6, 0, 2}});
    const auto segments = kb_segments(points, {});
    REQUIRE(segments.size() == 3);
    const Vec3 expected = (-1.0 * points[0].position + 9.0 * points[1].position + 9.0 * points[2].position -
                           points[3].position) * (1.0 / 16.0);
    require_near(segments[1].point_at(0.5), expected);
}

TEST_CASE("with c = b = 0 a segment equals the thesis' Cardinal matrix M_C with s = (1-t)/2", "[animation][kb]")
{
    const std::array<Vec3, 4> p{{{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {5, 1, 2}}};
    for (double tension : {-1.0, -0.5, 0.0, 0.3, 1.0}) {
        const double s = (1.0 - tension) / 2.0;
        // Rows of M_C (thesis Ch. 2.2) applied to [P_{k-1} P_k P_{k+1} P_{k+2}].
        const double m[4][4] = {{-s, 2 - s, s - 2, s}, {2 * s, s - 3, 3 - 2 * s, -s}, {-s, 0, s, 0}, {0, 1, 0, 0}};
        const ControlPoints points = points_with({p[0], p[1], p[2], p[3]}, {tension, 0, 0, 0});
        const auto segments = kb_segments(points, {});
        for (double u : {0.0, 0.2, 0.5, 0.9, 1.0}) {
            const double powers[4] = {u * u * u, u * u, u, 1};
            Vec3 expected;
            for (int row = 0; row < 4; ++row)
                for (int column = 0; column < 4; ++column)
                    expected += powers[row] * m[row][column] * p[static_cast<std::size_t>(column)];
            CAPTURE(tension, u);
            require_near(segments[1].point_at(u), expected, 1e-12);
        }
    }
}

TEST_CASE("tension 1 with end slopes 0 makes every segment a straight line", "[animation][kb]")
{
    const ControlPoints points = points_with(zigzag, {1, 0, 0, 0});
    const auto segments = kb_segments(points, {0.0, 0.0});
    for (const HermiteSegment& segment : segments) {
        REQUIRE(segment.start_tangent == Vec3{});
        REQUIRE(segment.end_tangent == Vec3{});
        for (double u : {0.1, 0.37, 0.5, 0.81})
            REQUIRE(std::abs(cross_z(segment.point_at(u) - segment.start, segment.end - segment.start)) < 1e-12);
    }
}

TEST_CASE("continuity -1 makes a corner: each side's tangent follows its own chord", "[animation][kb]")
{
    const ControlPoints points = points_with(zigzag, {0, -1, 0, 0});
    const auto segments = kb_segments(points, {});
    for (std::size_t k = 1; k + 1 < points.size(); ++k) {
        const Vec3 incoming_chord = points[k].position - points[k - 1].position;
        const Vec3 outgoing_chord = points[k + 1].position - points[k].position;
        // DS_k = (1−c)/2·(P_k − P_{k−1}) = P_k − P_{k−1}; DD_k = P_{k+1} − P_k.
        require_near(segments[k - 1].end_tangent, incoming_chord);
        require_near(segments[k].start_tangent, outgoing_chord);
        REQUIRE(std::abs(cross_z(segments[k - 1].derivative_at(1.0), segments[k].derivative_at(0.0))) > 1.0);
    }
}

TEST_CASE("continuity 0 keeps the tangent continuous at every interior control point", "[animation][kb]")
{
    const auto segments = kb_segments(points_with(zigzag), {});
    for (std::size_t k = 1; k < segments.size(); ++k)
        require_near(segments[k - 1].derivative_at(1.0), segments[k].derivative_at(0.0), 1e-12);
}

TEST_CASE("bias 1 follows the incoming chord and bias -1 the outgoing one", "[animation][kb]")
{
    // Thesis Eq. 3.1.3: DS = DD = [(1+b)(P_k−P_{k−1}) + (1−b)(P_{k+1}−P_k)]/2.
    for (const double bias : {1.0, -1.0}) {
        const ControlPoints points = points_with(zigzag, {0, 0, bias, 0});
        const auto segments = kb_segments(points, {});
        for (std::size_t k = 1; k + 1 < points.size(); ++k) {
            const Vec3 chord = bias > 0 ? points[k].position - points[k - 1].position
                                        : points[k + 1].position - points[k].position;
            require_near(segments[k - 1].end_tangent, chord);
            require_near(segments[k].start_tangent, chord);
        }
    }
    // On the zigzag's peak P_1 = (2,3), bias 1 carries the rising motion past the peak: the curve
    // just after P_1 is higher than with bias −1.
    const auto leaning_on = kb_segments(points_with(zigzag, {0, 0, 1, 0}), {});
    const auto leaning_off = kb_segments(points_with(zigzag, {0, 0, -1, 0}), {});
    REQUIRE(leaning_on[1].point_at(0.1).y > leaning_off[1].point_at(0.1).y);
}

TEST_CASE("end slopes scale the first and last tangents by the end chords", "[animation][kb]")
{
    const ControlPoints points = points_with(zigzag);
    const Vec3 first_chord = points[1].position - points[0].position;
    const Vec3 last_chord = points[4].position - points[3].position;
    const auto full = kb_segments(points, {1.0, 1.0});
    require_near(full.front().derivative_at(0.0), first_chord);
    require_near(full.back().derivative_at(1.0), last_chord);
    const auto flat = kb_segments(points, {0.0, 0.0});
    require_near(flat.front().derivative_at(0.0), {});
    require_near(flat.back().derivative_at(1.0), {});
    const auto half = kb_segments(points, {0.5, 0.25});
    require_near(half.front().derivative_at(0.0), 0.5 * first_chord);
    require_near(half.back().derivative_at(1.0), 0.25 * last_chord);
}

TEST_CASE("the sampled curve passes through every control point", "[animation][kb]")
{
    for (const StaffValues staff : {StaffValues{}, StaffValues{0.7, -0.4, 0.3, 0}, StaffValues{-1, 1, -1, 0}}) {
        const ControlPoints points = points_with(zigzag, staff);
        for (int samples : {1, 3, 32}) {
            const SampledCurve curve = sample_curve(kb_segments(points, {0.3, 0.8}), samples);
            REQUIRE(curve.sample_count() == (points.size() - 1) * static_cast<std::size_t>(samples) + 1);
            for (std::size_t k = 0; k < points.size(); ++k)
                REQUIRE(curve.sample(k * static_cast<std::size_t>(samples)) == points[k].position);
        }
    }
}

TEST_CASE("two control points with slopes 1 give the straight chord at uniform speed", "[animation][kb]")
{
    // F2 + F3 + F4 = u, so P(u) = P0 + u·(P1 − P0).
    const auto segments = kb_segments(points_with({{0, 0, 0}, {4, 2, -2}}), {1, 1});
    REQUIRE(segments.size() == 1);
    require_near(segments[0].point_at(0.25), {1, 0.5, -0.5});
}

TEST_CASE("fewer than two control points give no segments", "[animation][kb]")
{
    REQUIRE(kb_segments(points_with({{1, 2, 3}}), {}).empty());
    REQUIRE(kb_segments({}, {}).empty());
    REQUIRE(sample_curve({}, 32).sample_count() == 0);
}

TEST_CASE("tension, continuity and bias beyond -1 and +1 are clamped: 3 shapes the curve as 1 does", "[animation][kb]")
{
    const std::array<Vec3, 3> p{{{0, 0, 0}, {2, 3, 1}, {5, 1, -1}}};
    for (const StaffLine line : {StaffLine::tension, StaffLine::continuity, StaffLine::bias}) {
        for (const double sign : {1.0, -1.0}) {
            StaffValues beyond{0.2, -0.3, 0.4, 0};
            StaffValues bound = beyond;
            beyond[line] = 3.0 * sign;
            bound[line] = sign;
            CAPTURE(staff_line_name(line), sign);
            REQUIRE(incoming_tangent(p[0], p[1], p[2], beyond) == incoming_tangent(p[0], p[1], p[2], bound));
            REQUIRE(outgoing_tangent(p[0], p[1], p[2], beyond) == outgoing_tangent(p[0], p[1], p[2], bound));
        }
    }
}

TEST_CASE("end slopes beyond 0 and 1 are clamped: 3 gives the tangent of 1, -2 that of 0", "[animation][kb]")
{
    const ControlPoints points = points_with(zigzag);
    const auto beyond = kb_segments(points, {3.0, -2.0});
    const auto bound = kb_segments(points, {1.0, 0.0});
    REQUIRE(beyond.front().start_tangent == bound.front().start_tangent);
    REQUIRE(beyond.back().end_tangent == bound.back().end_tangent);
}

// Opening a path of 10^6 control points made its 96 MB of segments on one core, in 4 KB pages
// faulted in one by one (PERFORMANCE.md 19: the editor's opening took 494 ms then, 261 ms after).
TEST_CASE("a long path's segments, made on both cores into 2 MB pages, are each kb_segment's", "[animation][kb]")
{
    // More than twice the points a thread is worth, for two halves.
    ControlPoints points;
    for (int k = 0; k < 50'000; ++k)
        points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.5, std::cos(k * 0.7) * 4.0},
                          {std::sin(k * 0.3) * 0.5, std::cos(k * 0.2) * 0.5, k % 3 == 0 ? 0.4 : -0.2, 0}});
    const EndSlopes slopes{0.3, 0.8};
    HermiteSegments segments(7); // room of another path's, made again
    kb_segments(points, slopes, segments);
    REQUIRE(segments.size() == points.size() - 1);
    for (std::size_t k = 0; k < segments.size(); ++k)
        if (segments[k] != kb_segment(points, slopes, k))
            FAIL("segment " << k << " differs");
    const std::vector<HermiteSegment> returned = kb_segments(points, slopes);
    REQUIRE(std::equal(returned.begin(), returned.end(), segments.begin(), segments.end()));
    // 2 MB pages for an array of 2 MB and more: 96 bytes a segment.
    HermiteSegments long_path(1'000'000);
    test::check_advised_for_huge_pages(&long_path[500'000]);
}
