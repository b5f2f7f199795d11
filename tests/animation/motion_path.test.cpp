#include "apcs/animation/arc_length.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/sampled_curve.h"
#include "apcs/animation/waypoint_change.h"

#include "support/same_path.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace apcs;
using apcs::test::require_same_path;

namespace {

ControlPoints curved_path(double acceleration = 0.0)
{
    ControlPoints points;
    for (const Vec3& position : {Vec3{0, 0, 0}, Vec3{3, 4, 0}, Vec3{7, 3, 1}, Vec3{10, 6, 0}})
        points.push_back({position, {0, 0, 0, acceleration}});
    return points;
}

std::vector<double> positions_along(const EvaluatedPath& path)
{
    std::vector<double> distances;
    for (const Inbetween& inbetween : path.inbetweens)
        distances.push_back(inbetween.arc_fraction * path.curve.total_length());
    return distances;
}

double widest_sample_gap(const SampledCurve& curve)
{
    double widest = 0.0;
    for (std::size_t i = 1; i < curve.sample_count(); ++i)
        widest = std::max(widest, curve.chord_length(i) - curve.chord_length(i - 1));
    return widest;
}

} // namespace

TEST_CASE("acceleration 0 spaces the in-betweens equally to within one sample", "[animation][acceleration]")
{
    const EvaluatedPath path = evaluate_path(curved_path(), {{}, 32, 12, Spacing::nearest});
    REQUIRE(path.inbetweens.size() == 12);
    REQUIRE_FALSE(path.frames_freeze());
    const double length = path.curve.total_length();
    const double tolerance = widest_sample_gap(path.curve) / 2.0 + 1e-12;
    const std::vector<double> distances = positions_along(path);
    for (std::size_t j = 0; j < distances.size(); ++j) {
        // d_j = L·j/(M+1); the nearest sample is at most half a sample gap away.
        CAPTURE(j);
        REQUIRE(std::abs(distances[j] - length * static_cast<double>(j + 1) / 13.0) <= tolerance);
    }
}

TEST_CASE("negative acceleration shrinks the gaps and positive acceleration grows them", "[animation][acceleration]")
{
    for (const double acceleration : {-1.0, -0.5, 0.5, 1.0}) {
        // Enough samples that rounding to a sample cannot reverse a gap's trend.
        const EvaluatedPath path = evaluate_path(curved_path(acceleration), {{}, 2000, 10, Spacing::nearest});
        const std::vector<double> distances = positions_along(path);
        for (std::size_t j = 2; j < distances.size(); ++j) {
            const double earlier_gap = distances[j - 1] - distances[j - 2];
            const double later_gap = distances[j] - distances[j - 1];
            CAPTURE(acceleration, j, earlier_gap, later_gap);
            if (acceleration < 0)
                REQUIRE(later_gap < earlier_gap);
            else
                REQUIRE(later_gap > earlier_gap);
        }
    }
}

TEST_CASE("the acceleration targets follow d = L((1-|a|)tau + |a|w(tau)) worked by hand", "[animation][acceleration]")
{
    // A straight two-point path from 0 to 12 with slopes 1: samples are evenly spaced (P(u) = 12u),
    // 120 samples put one every 0.1. M = 1: tau = 1/2. a = −1: d = 12·sin(π/4) = 8.485 → 8.5.
    ControlPoints points{{{0, 0, 0}, {0, 0, 0, -1}}, {{12, 0, 0}, {}}};
    EvaluatedPath path = evaluate_path(points, {{}, 120, 1, Spacing::nearest});
    REQUIRE(path.inbetweens.size() == 1);
    REQUIRE(path.inbetweens[0].position.x == Approx(8.5).epsilon(1e-12));
    // a = 0.5: d = 12·(0.5·0.5 + 0.5·(1 − cos(π/4))) = 12·0.396447 = 4.757 → 4.8.
    points[0].staff.acceleration = 0.5;
    path = evaluate_path(points, {{}, 120, 1, Spacing::nearest});
    REQUIRE(path.inbetweens[0].position.x == Approx(4.8).epsilon(1e-12));
}

TEST_CASE("exact spacing hits its arc-length targets within 1e-6 of the length", "[animation][acceleration]")
{
    for (const double acceleration : {0.0, -0.7, 0.9}) {
        const ControlPoints points = curved_path(acceleration);
        const EvaluatedPath path = evaluate_path(points, {{}, 8, 9, Spacing::exact});
        const ArcLengthTable table(path.curve.segments);
        const double length = table.total_length();
        REQUIRE(path.inbetweens.size() == 9);
        for (std::size_t j = 0; j < path.inbetweens.size(); ++j) {
            const double tau = static_cast<double>(j + 1) / 10.0;
            const double target = length * path.inbetweens[j].arc_fraction;
            const double expected_fraction = acceleration == 0.0 ? tau
                : acceleration < 0 ? (1 + acceleration) * tau - acceleration * std::sin(M_PI * tau / 2)
                                   : (1 - acceleration) * tau + acceleration * (1 - std::cos(M_PI * tau / 2));
            REQUIRE(path.inbetweens[j].arc_fraction == Approx(expected_fraction).margin(1e-12));
            const CurveParameter parameter = table.parameter_at(target);
            REQUIRE(std::abs(table.length_at(parameter) - target) <= 1e-6 * length);
            REQUIRE(distance(table.point_at(parameter), path.inbetweens[j].position) <= 1e-12);
        }
    }
}

TEST_CASE("two spans with different accelerations share the in-betweens by length", "[animation][acceleration]")
{
    ControlPoints points = curved_path();
    points[0].staff.acceleration = 0.8;
    points[1].staff.acceleration = 0.8;
    points[2].staff.acceleration = -0.8;
    const auto spans = acceleration_spans(points);
    REQUIRE(spans.size() == 2);
    REQUIRE(spans[0].first_point == 0);
    REQUIRE(spans[0].last_point == 2);
    REQUIRE(spans[1].first_point == 2);
    REQUIRE(spans[1].last_point == 3);

    const EvaluatedPath path = evaluate_path(points, {{}, 400, 12, Spacing::nearest});
    const double boundary = path.curve.length_to_point[2];
    const double length = path.curve.total_length();
    const std::vector<double> distances = positions_along(path);
    const auto in_first = static_cast<std::size_t>(std::count_if(distances.begin(), distances.end(),
                                                                 [&](double d) { return d < boundary; }));
    const std::vector<double> weights{boundary, length - boundary};
    REQUIRE(in_first == static_cast<std::size_t>(share_by_largest_remainder(weights, 12)[0]));
    // Gaps grow inside the first span (a > 0) and shrink inside the second (a < 0).
    for (std::size_t j = 2; j < in_first; ++j)
        REQUIRE(distances[j] - distances[j - 1] > distances[j - 1] - distances[j - 2]);
    for (std::size_t j = in_first + 2; j < distances.size(); ++j)
        REQUIRE(distances[j] - distances[j - 1] < distances[j - 1] - distances[j - 2]);
}

TEST_CASE("a span runs on to the next control point whose acceleration differs", "[animation][acceleration]")
{
    ControlPoints points = curved_path();
    points[3].staff.acceleration = 1.0; // the last point's a is unused
    REQUIRE(acceleration_spans(points).size() == 1);
    points[1].staff.acceleration = 0.5;
    const auto spans = acceleration_spans(points);
    REQUIRE(spans.size() == 3);
    REQUIRE(spans[1].first_point == 1);
    REQUIRE(spans[1].last_point == 2);
    REQUIRE(spans[1].acceleration == 0.5);
}

TEST_CASE("the spans after a waypoint edit, read around the edit alone, are the spans read afresh",
          "[animation][acceleration]")
{
    // Runs of accelerations, an insert, delete or move anywhere (the ends too), and acceleration
    // changes that make, join or move a span's start; 1.5 and 2.0 clamp alike (one span).
    ControlPoints points;
    for (int k = 0; k < 40; ++k)
        points.push_back({{static_cast<double>(k), std::sin(k * 0.5), 0.0}, {0, 0, 0, (k / 7) % 3 == 1 ? 0.5 : 0.0}});
    points[20].staff.acceleration = 1.5;
    points[21].staff.acceleration = 2.0;
    const ControlPoint inserted{{0.5, 0.5, 0.5}, {0, 0, 0, 0.5}};
    struct Edit {
        PathChange change;
        double acceleration; // of the inserted point, or set on the changed ones
    };
    const std::vector<Edit> edits{
        {{1, 0, 1}, 0.5},   {{10, 0, 1}, 0.0},  {{14, 0, 1}, 0.5}, {{41, 0, 1}, 0.0},  {{5, 1, 0}, 0.0},
        {{13, 1, 0}, 0.0},  {{39, 1, 0}, 0.0},  {{7, 1, 1}, 0.5},  {{8, 1, 1}, 0.0},   {{0, 1, 1}, -0.5},
        {{20, 2, 2}, 1.0},  {{30, 3, 3}, 0.25}, {{38, 1, 1}, 0.9}, {{0, 0, 1}, 0.0},   {{2, 1, 0}, 0.0},
        // At the end: the last point's acceleration starts no span, until a point is appended
        // after it; deleting the last point makes the one before it last.
        {{40, 1, 1}, 0.5},  {{41, 0, 1}, 0.5},  {{42, 0, 1}, 0.0}, {{42, 1, 0}, 0.0},  {{41, 1, 0}, 0.0},
        {{39, 1, 1}, 0.7},  {{40, 0, 1}, 0.7},  {{40, 1, 0}, 0.0}};
    std::vector<AccelerationSpan> spans = acceleration_spans(points);
    for (const Edit& edit : edits) {
        const PathChange& change = edit.change;
        CAPTURE(change.first, change.removed, change.inserted);
        const auto at = points.begin() + static_cast<std::ptrdiff_t>(change.first);
        if (change.inserted > change.removed) {
            ControlPoint point = inserted;
            point.staff.acceleration = edit.acceleration;
            points.insert(at, point);
        } else if (change.removed > change.inserted) {
            points.erase(at);
        } else {
            for (std::size_t k = change.first; k < change.first + change.inserted; ++k)
                points[k].staff.acceleration = edit.acceleration;
        }
        spans = acceleration_spans_after(spans, points, change);
        const std::vector<AccelerationSpan> afresh = acceleration_spans(points);
        REQUIRE(spans.size() == afresh.size());
        for (std::size_t s = 0; s < spans.size(); ++s) {
            CAPTURE(s);
            REQUIRE(spans[s].first_point == afresh[s].first_point);
            REQUIRE(spans[s].last_point == afresh[s].last_point);
            REQUIRE(spans[s].acceleration == afresh[s].acceleration);
        }
    }
}

TEST_CASE("largest remainder shares worked by hand", "[animation][acceleration]")
{
    // Quotas 12·(5, 3, 2)/10 = 6, 3.6, 2.4: floors 6, 3, 2 and the one left goes to 3.6.
    const std::vector<double> weights{5, 3, 2};
    REQUIRE(share_by_largest_remainder(weights, 12) == std::vector<int>{6, 4, 2});
    const std::vector<double> none{0, 0, 0};
    REQUIRE(share_by_largest_remainder(none, 4) == std::vector<int>{2, 1, 1});
    REQUIRE(share_by_largest_remainder(weights, 0) == std::vector<int>{0, 0, 0});
}

TEST_CASE("more in-betweens than samples freeze frames", "[animation][acceleration]")
{
    const EvaluatedPath path = evaluate_path(curved_path(), {{}, 2, 10, Spacing::nearest});
    REQUIRE(path.curve.sample_count() == 7);
    REQUIRE(path.frames_freeze());
    REQUIRE(path.inbetweens.size() == 10);
}

TEST_CASE("two in-betweens on one sample freeze frames even when there are fewer than samples",
          "[animation][acceleration]")
{
    // A straight 2-point path, 4 samples (chord 0, 1/4 … 1 of the length) and 3 in-betweens.
    ControlPoints points{{{0, 0, 0}, {}}, {{0, 8, 0}, {}}};
    // a = 0: targets 1/4, 1/2, 3/4 of the length land on samples 1, 2, 3: no two alike.
    REQUIRE_FALSE(evaluate_path(points, {{}, 4, 3, Spacing::nearest}).frames_freeze());
    // a = 1, 5 in-betweens: targets 1 − cos(πτ/2) for τ = 2/6 and 3/6 are 0.134 and 0.293 of the
    // length, both nearest to sample 1 (0.25): a repeated frame.
    points[0].staff.acceleration = 1.0;
    const EvaluatedPath repeated = evaluate_path(points, {{}, 4, 5, Spacing::nearest});
    REQUIRE(repeated.inbetweens[1].sample_index == repeated.inbetweens[2].sample_index);
    REQUIRE(repeated.frames_freeze());
    // The exact spacing never repeats a position on a path of length.
    REQUIRE_FALSE(evaluate_path(points, {{}, 4, 5, Spacing::exact}).frames_freeze());
}

TEST_CASE("an evaluated path clamps what it is given: staff values of 3 and slopes of 3 act as 1",
          "[animation][acceleration]")
{
    const auto inbetweens = [](const ControlPoints& points, EndSlopes slopes) {
        std::vector<Vec3> positions;
        for (const Inbetween& inbetween : evaluate_path(points, {slopes, 32, 12, Spacing::nearest}).inbetweens)
            positions.push_back(inbetween.position);
        return positions;
    };
    const auto with_staff = [](const StaffValues& staff) {
        ControlPoints points = curved_path();
        for (ControlPoint& point : points)
            point.staff = staff;
        return points;
    };
    REQUIRE(inbetweens(curved_path(), {3.0, 3.0}) == inbetweens(curved_path(), {1.0, 1.0}));
    REQUIRE(inbetweens(with_staff({0.5, -3, 3, 3}), {}) == inbetweens(with_staff({0.5, -1, 1, 1}), {}));
    REQUIRE(inbetweens(with_staff({-3, 0, 0, -3}), {}) == inbetweens(with_staff({-1, 0, 0, -1}), {}));
}

TEST_CASE("accelerations of 3 and 1 are one span, as 1 and 1 are", "[animation][acceleration]")
{
    ControlPoints points = curved_path(1.0);
    points[1].staff.acceleration = 3.0;
    const std::vector<AccelerationSpan> spans = acceleration_spans(points);
    REQUIRE(spans.size() == 1);
    REQUIRE(spans[0].acceleration == 1.0);
    REQUIRE(spans[0].last_point == points.size() - 1);
}

TEST_CASE("a path of zero length progresses by its first control point's acceleration law", "[animation][path]")
{
    ControlPoints points{{{1, 2, 3}, {0, 0, 0, 0.5}}, {{1, 2, 3}, {0, 0, 0, -1}}, {{1, 2, 3}, {}}};
    const EvaluatedPath path = evaluate_path(points, {{}, 8, 3, Spacing::exact});
    REQUIRE(path.inbetweens.size() == 3);
    for (std::size_t j = 0; j < 3; ++j) {
        const double tau = static_cast<double>(j + 1) / 4.0;
        // (1 − a)·τ + a·(1 − cos(πτ/2)) with a = 0.5, worked out: τ = 1/4 gives 0.125 + 0.5·0.0761205.
        const double expected = 0.5 * tau + 0.5 * (1.0 - std::cos(std::numbers::pi * tau / 2.0));
        CAPTURE(j);
        REQUIRE(path.inbetweens[j].arc_fraction == Approx(expected).epsilon(1e-12));
        REQUIRE(path.inbetweens[j].position == Vec3{1, 2, 3});
    }
    REQUIRE(path.inbetweens[0].arc_fraction == Approx(0.125 + 0.5 * 0.07612046748871326).epsilon(1e-12));
}

TEST_CASE("a path evaluated into the arrays of an earlier one is the path evaluated afresh", "[animation][path]")
{
    ControlPoints long_path;
    for (int k = 0; k < 40; ++k)
        long_path.push_back({{std::sin(k * 0.9), k * 2.0, std::cos(k * 0.7)}, {0.2, 0, 0, 0.5}});
    const ControlPoints short_path{{{0, 0, 0}, {}}, {{0, 3, 5}, {}}, {{0, 7, 1}, {-0.5, 0, 0, -1}}};
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact}) {
        const PathSettings settings{{}, 16, 7, spacing};
        EvaluatedPath reused;
        evaluate_path(long_path, settings, reused); // large arrays first, then a short path into them
        evaluate_path(short_path, settings, reused);
        const EvaluatedPath fresh = evaluate_path(short_path, settings);
        require_same_path(reused, fresh);
    }
}

TEST_CASE("a long curve measured on two cores is the curve measured in order, to the bit", "[animation][path]")
{
    // 10000 segments: past the two-core threshold (8192).
    ControlPoints points;
    for (int k = 0; k <= 10000; ++k)
        points.push_back({{std::sin(k * 0.3), k * 0.5, std::cos(k * 0.11)}, {0.1, -0.2, 0.3, 0}});
    const std::vector<HermiteSegment> segments = kb_segments(points, {});
    const SampledCurve curve = sample_curve(segments, 8);
    const std::vector<HermiteBasis> table = hermite_basis_table(8);
    std::vector<Vec3> expected_points{segments.front().start};
    std::vector<double> expected_in_segment{0.0};
    LargeArray<double> expected_to_point{0.0};
    for (const HermiteSegment& segment : segments) {
        double length = 0.0;
        for (std::size_t j = 1; j < table.size(); ++j) {
            const Vec3 point = j + 1 == table.size() ? segment.end : segment.apply(table[j]);
            length += distance(expected_points.back(), point);
            expected_in_segment.push_back(j + 1 == table.size() ? 0.0 : length);
            expected_points.push_back(point);
        }
        expected_to_point.push_back(expected_to_point.back() + length);
    }
    REQUIRE(curve.samples() == expected_points);
    REQUIRE(curve.length_to_point == expected_to_point);
    for (std::size_t i = 0; i < expected_points.size(); i += 7) {
        CAPTURE(i);
        REQUIRE(curve.chord_length(i) == expected_to_point[i / 8] + expected_in_segment[i]);
    }
}

TEST_CASE("the nearest sample is the one nearest in chord length, the earlier on a tie", "[animation][path]")
{
    // Two straight segments of lengths 4 and 2 (every tangent 0: end slopes 0, tension 1 between),
    // two samples each, at their middles: chord lengths 0, 2, 4, 5, 6.
    const ControlPoints points{{{0, 0, 0}, {}}, {{4, 0, 0}, {1, 0, 0, 0}}, {{4, 2, 0}, {}}};
    const SampledCurve curve = sample_curve(kb_segments(points, {0, 0}), 2);
    REQUIRE(curve.sample_count() == 5);
    std::vector<double> lengths;
    for (std::size_t i = 0; i < curve.sample_count(); ++i)
        lengths.push_back(curve.chord_length(i));
    REQUIRE(lengths == std::vector<double>{0, 2, 4, 5, 6});
    CHECK(curve.nearest_sample(-1.0) == 0);
    CHECK(curve.nearest_sample(0.9) == 0);
    CHECK(curve.nearest_sample(1.0) == 0); // a tie: the earlier
    CHECK(curve.nearest_sample(1.1) == 1);
    CHECK(curve.nearest_sample(4.0) == 2);
    CHECK(curve.nearest_sample(4.5) == 2);
    CHECK(curve.nearest_sample(4.6) == 3);
    CHECK(curve.nearest_sample(5.9) == 4);
    CHECK(curve.nearest_sample(7.0) == 4);
}

namespace {

// SampledCurve::nearest_sample as it was first written: a binary search over every sample's
// chord_length, then the nearer of the two around the target.
std::size_t nearest_sample_by_search(const SampledCurve& curve, double target)
{
    std::size_t low = 0;
    std::size_t high = curve.sample_count();
    while (low < high) {
        const std::size_t middle = low + (high - low) / 2;
        (curve.chord_length(middle) < target ? low = middle + 1 : high = middle);
    }
    if (low == 0)
        return 0;
    if (low == curve.sample_count())
        return curve.sample_count() - 1;
    return target - curve.chord_length(low - 1) <= curve.chord_length(low) - target ? low - 1 : low;
}

} // namespace

TEST_CASE("nearest samples found one target after another are those of a search over every sample",
          "[animation][path]")
{
    ControlPoints points;
    for (int k = 0; k < 40; ++k) // bent segments, and two of no length (a point repeated)
        points.push_back({k == 20 || k == 21 ? Vec3{5, 5, 5} : Vec3{std::sin(k * 0.9) * 3.0, k * 0.5, std::cos(k * 1.3)},
                          {std::sin(k * 0.4), 0, 0, 0}});
    points[21].position = points[20].position;
    points[22].position = points[20].position;
    for (const int samples : {1, 2, 7, 32}) {
        const SampledCurve curve = sample_curve(kb_segments(points, {}), samples);
        const double total = curve.total_length();
        // Rising targets (as in-betweens rise), every sample's own chord length and the midpoints
        // between neighbours (ties), falling ones, and some outside the curve.
        std::vector<double> targets{-1.0, 0.0};
        for (int j = 1; j < 500; ++j)
            targets.push_back(total * j / 500.0);
        for (std::size_t i = 0; i < curve.sample_count(); ++i) {
            targets.push_back(curve.chord_length(i));
            if (i > 0)
                targets.push_back((curve.chord_length(i - 1) + curve.chord_length(i)) / 2.0);
        }
        for (int j = 300; j > 0; --j)
            targets.push_back(total * j / 301.0);
        targets.push_back(total);
        targets.push_back(total * 2.0);
        NearestSamples nearest(curve);
        for (const double target : targets) {
            CAPTURE(samples, target);
            const NearestSamples::Found found = nearest(target);
            REQUIRE(found.sample == nearest_sample_by_search(curve, target));
            REQUIRE(found.chord_length == curve.chord_length(found.sample));
            REQUIRE(curve.nearest_sample(target) == found.sample);
        }
    }
}

TEST_CASE("many in-betweens on finely sampled segments are placed as a search for each would place them",
          "[animation][path]")
{
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact}) {
        PathSettings settings;
        settings.samples_per_segment = 500;
        settings.inbetween_count = 3000;
        settings.spacing = spacing;
        ControlPoints points = curved_path();
        points[1].staff.acceleration = 0.8; // two spans, one slowing down
        const EvaluatedPath path = evaluate_path(points, settings);
        REQUIRE(path.inbetweens.size() == 3000);
        const double chord_total = path.curve.total_length();
        for (const Inbetween& inbetween : path.inbetweens) {
            CAPTURE(spacing, inbetween.arc_fraction);
            if (spacing == Spacing::exact) {
                REQUIRE(inbetween.sample_index == nearest_sample_by_search(path.curve, inbetween.arc_fraction * chord_total));
                continue;
            }
            REQUIRE(inbetween.position == path.curve.sample(inbetween.sample_index));
            REQUIRE(inbetween.arc_fraction == path.curve.chord_length(inbetween.sample_index) / chord_total);
        }
    }
}

TEST_CASE("a path re-evaluated after a change to some control points is the path evaluated afresh, to the bit",
          "[animation][path]")
{
    ControlPoints points;
    for (int k = 0; k < 12000; ++k) // past the two-core threshold, for a global change
        points.push_back({{std::sin(k * 0.9), k * 2.0, std::cos(k * 0.7)}, {0.2, 0, 0, 0.5}});
    struct Change {
        std::size_t first;
        std::size_t last;
        StaffValues staff;
    };
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact}) {
        const PathSettings settings{{0.5, 1}, 8, 12, spacing};
        EvaluatedPath path = evaluate_path(points, settings);
        ControlPoints changed = points;
        for (const Change& change : {Change{0, 0, {0.5, 0, 0, 0.5}}, Change{5, 9, {-0.3, 0.4, 0.1, 0.5}},
                                     Change{11999, 11999, {0.9, 0, 0, 0.5}}, Change{100, 4000, {0.2, 0, 0, -0.7}},
                                     Change{3000, 3500, {0.4, 0.1, 0, -0.7}}, // the spans kept
                                     Change{0, 11999, {-0.1, 0.2, -0.3, 0.1}}}) {
            CAPTURE(change.first, change.last);
            for (std::size_t k = change.first; k <= change.last; ++k)
                changed[k].staff = change.staff;
            reevaluate_path(changed, settings, path, change.first, change.last);
            require_same_path(path, evaluate_path(changed, settings));
        }
        // A region outside the path: evaluated afresh, never read past the end.
        reevaluate_path(changed, settings, path, 20000, 20005);
        require_same_path(path, evaluate_path(changed, settings));
    }
}

TEST_CASE("the acceleration spans of 300000 control points, found in two halves, are found in order",
          "[animation][acceleration]")
{
    ControlPoints points(300000);
    for (std::size_t k = 0; k < points.size(); ++k)
        points[k].staff.acceleration = (k / 1000) % 4 == 1 ? 0.5 : (k % 150001 == 0 ? 3.0 : 0.0); // 3.0 clamps to 1
    std::vector<AccelerationSpan> expected;
    AccelerationSpan current{0, points.size() - 1, 1.0}; // point 0's 3.0, clamped
    for (std::size_t k = 1; k + 1 < points.size(); ++k) {
        const double acceleration = std::clamp(points[k].staff.acceleration, -1.0, 1.0);
        if (acceleration != current.acceleration) {
            current.last_point = k;
            expected.push_back(current);
            current = {k, points.size() - 1, acceleration};
        }
    }
    expected.push_back(current);
    const std::vector<AccelerationSpan> spans = acceleration_spans(points);
    REQUIRE(spans.size() == expected.size());
    REQUIRE(spans.size() > 100);
    for (std::size_t s = 0; s < spans.size(); ++s) {
        CAPTURE(s);
        REQUIRE(spans[s].first_point == expected[s].first_point);
        REQUIRE(spans[s].last_point == expected[s].last_point);
        REQUIRE(spans[s].acceleration == expected[s].acceleration);
    }
}

TEST_CASE("a path re-evaluated after control points were inserted, deleted or moved is the path evaluated afresh, "
          "to the bit",
          "[animation][path]")
{
    ControlPoints points;
    for (int k = 0; k < 12000; ++k)
        points.push_back({{std::sin(k * 0.9), k * 2.0, std::cos(k * 0.7)}, {0.2, 0, 0, k < 6000 ? 0.5 : -0.3}});
    std::vector<std::size_t> origins = file_origins(points.size());
    const auto inserted = [](std::size_t index) {
        WaypointChange change;
        change.kind = WaypointChange::Kind::insert;
        change.index = index;
        change.point = {{0.5, static_cast<double>(index) * 2.0 - 1.0, 3.0}, {0.1, 0.2, 0.3, 0.4}};
        return change;
    };
    const auto removed = [&](std::size_t index) {
        WaypointChange change;
        change.kind = WaypointChange::Kind::remove;
        change.index = index;
        change.point = points[index];
        return change;
    };
    const auto moved = [](std::size_t index) {
        WaypointChange change;
        change.index = index;
        change.offset = {0.3, -0.2, 0.7};
        return change;
    };
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact}) {
        const PathSettings settings{{0.5, 1}, 8, 12, spacing};
        EvaluatedPath path = evaluate_path(points, settings);
        for (const std::size_t index : {std::size_t{1}, std::size_t{2}, std::size_t{5000}, std::size_t{5999},
                                        std::size_t{6000}, std::size_t{11998}}) {
            CAPTURE(index);
            for (const WaypointChange& change : {moved(index), inserted(index), removed(index), inserted(index + 1)}) {
                CAPTURE(static_cast<int>(change.kind));
                const PathChange touched = apply_change(points, origins, change);
                reevaluate_path(points, settings, path, touched);
                const EvaluatedPath fresh = evaluate_path(points, settings);
                require_same_path(path, fresh);
                REQUIRE(path.arc_lengths.total_length() == fresh.arc_lengths.total_length());
                REQUIRE(path.arc_lengths.length_to_segment_start(index) == fresh.arc_lengths.length_to_segment_start(index));
            }
        }
    }
}

TEST_CASE("the segments a change reports made again are the only ones that differ from before", "[animation][path]")
{
    ControlPoints points;
    for (int k = 0; k < 40; ++k)
        points.push_back({{std::sin(k * 0.9), k * 2.0, std::cos(k * 0.7)}, {}});
    std::vector<std::size_t> origins = file_origins(points.size());
    const PathSettings settings{{0.5, 1}, 8, 12, Spacing::exact};
    EvaluatedPath path = evaluate_path(points, settings);
    const HermiteSegments before = path.curve.segments;
    WaypointChange change;
    change.kind = WaypointChange::Kind::insert;
    change.index = 20;
    change.point = {{3, 39, 1}, {}};
    // The change first: the span of the points is taken after the insertion, whichever order a
    // compiler evaluates a call's arguments in (Clang took it before, with the old size).
    const PathChange applied = apply_change(points, origins, change);
    const SegmentSplice touched = reevaluate_path(points, settings, path, applied);
    // A segment's shape depends on the points around its ends (s − 1 … s + 2): the new point 20
    // shapes new segments 18 … 21, in place of old 18 … 20, whose end tangents at old points 19
    // and 20 saw the neighbour it now stands between. No more: "everything" would pass the rest.
    REQUIRE(touched == SegmentSplice{18, 3, 4});
    REQUIRE(touched.inserted == touched.removed + 1);
    REQUIRE(path.curve.segments.size() == before.size() + 1);
    for (std::size_t s = 0; s < touched.first; ++s)
        REQUIRE(path.curve.segments[s] == before[s]);
    for (std::size_t s = touched.old_end(); s < before.size(); ++s)
        REQUIRE(path.curve.segments[s + 1] == before[s]);
}

TEST_CASE("frames that freeze are named by the pair, KEY1 and KEY2 included", "[animation][acceleration]")
{
    // A straight path of 4 samples (0, 1/4 … 1 of the length) and 3 in-betweens.
    ControlPoints points{{{0, 0, 0}, {}}, {{0, 8, 0}, {}}};
    // a = +1: 1 − cos(πτ/2) for τ = 1/4, 2/4, 3/4 is 0.076, 0.293, 0.617: samples 0, 1, 2.
    points[0].staff.acceleration = 1.0;
    const EvaluatedPath slow_start = evaluate_path(points, {{}, 4, 3, Spacing::nearest});
    REQUIRE(slow_start.frozen_frames == std::vector<std::size_t>{0});
    REQUIRE(describe_frozen_frames(slow_start, 8) == "KEY1=1");
    // a = −1: sin(πτ/2) is 0.383, 0.707, 0.924: samples 2, 3, 4, the last being KEY2's.
    points[0].staff.acceleration = -1.0;
    const EvaluatedPath slow_end = evaluate_path(points, {{}, 4, 3, Spacing::nearest});
    REQUIRE(slow_end.frozen_frames == std::vector<std::size_t>{3});
    REQUIRE(describe_frozen_frames(slow_end, 8) == "3=KEY2");
    // 2 samples, 5 in-betweens at a = 0: 1/6 … 5/6 land on samples 0, 1, 1, 1, 2.
    points[0].staff.acceleration = 0.0;
    const EvaluatedPath crowded = evaluate_path(points, {{}, 2, 5, Spacing::nearest});
    REQUIRE(crowded.frozen_frames == std::vector<std::size_t>{0, 2, 3, 5});
    REQUIRE(describe_frozen_frames(crowded, 8) == "KEY1=1, 2=3, 3=4, 5=KEY2");
    REQUIRE(describe_frozen_frames(crowded, 1) == "KEY1=1 and 3 more");
    REQUIRE_FALSE(evaluate_path(points, {{}, 2, 5, Spacing::exact}).frames_freeze());
}

TEST_CASE("a path of zero length says nothing of freezing: its frames are one point by nature",
          "[animation][acceleration]")
{
    const ControlPoints still{{{1, 2, 3}, {}}, {{1, 2, 3}, {}}};
    const EvaluatedPath path = evaluate_path(still, {{}, 4, 3, Spacing::nearest});
    REQUIRE(path.inbetweens.size() == 3);
    REQUIRE_FALSE(path.frames_freeze());
}
