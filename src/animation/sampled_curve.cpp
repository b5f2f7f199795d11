#include "apcs/animation/sampled_curve.h"

#include <algorithm>
#include <cassert>
#include <ranges>
#include <thread>

namespace apcs {

std::vector<HermiteBasis> hermite_basis_table(int samples_per_segment)
{
    const int samples = std::max(samples_per_segment, 1);
    std::vector<HermiteBasis> table;
    table.reserve(static_cast<std::size_t>(samples) + 1);
    for (int j = 0; j <= samples; ++j)
        table.push_back(hermite_basis(static_cast<double>(j) / samples));
    return table;
}

std::size_t SampledCurve::nearest_sample(double target) const
{
    const auto indices = std::views::iota(std::size_t{0}, points.size());
    const auto above = std::ranges::partition_point(indices, [&](std::size_t i) { return chord_length(i) < target; });
    if (above == indices.begin())
        return 0;
    if (above == indices.end())
        return points.size() - 1;
    const std::size_t upper = *above;
    const bool below_is_nearer = target - chord_length(upper - 1) <= chord_length(upper) - target;
    return below_is_nearer ? upper - 1 : upper;
}

SampledCurve sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment)
{
    SampledCurve curve;
    sample_curve(segments, samples_per_segment, curve);
    return curve;
}

namespace {

// Samples segments first … end − 1 and measures each: its samples' distances from its control
// point along the polyline, and its whole length. Segments are independent of each other.
void sample_segments(std::span<const HermiteSegment> segments, std::span<const HermiteBasis> table, std::size_t first,
                     std::size_t end, SampledCurve& curve)
{
    const std::size_t per_segment = table.size() - 1;
    for (std::size_t s = first; s < end; ++s) {
        const HermiteSegment& segment = segments[s];
        const std::size_t base = s * per_segment;
        Vec3 previous = segment.start;
        double length = 0.0;
        curve.points[base] = segment.start;
        curve.length_in_segment[base] = 0.0;
        for (std::size_t j = 1; j < per_segment; ++j) {
            const Vec3 point = segment.apply(table[j]);
            length += distance(previous, point);
            curve.points[base + j] = point;
            curve.length_in_segment[base + j] = length;
            previous = point;
        }
        // The last sample is the end control point itself, exactly, not a rounded evaluation.
        curve.segment_length[s] = length + distance(previous, segment.end);
    }
}

// A long path (a session's 10^5 control points: 3.2 million samples) is sampled on two cores; each
// segment is computed alike either way, so the curve is the same to the bit.
void sample_segments_on_cores(std::span<const HermiteSegment> segments, int samples_per_segment, std::size_t first,
                              std::size_t end, SampledCurve& curve)
{
    const std::vector<HermiteBasis> table = hermite_basis_table(samples_per_segment);
    constexpr std::size_t segments_worth_a_thread = 4096;
    if (end - first >= 2 * segments_worth_a_thread && std::thread::hardware_concurrency() > 1) {
        const std::size_t middle = first + (end - first) / 2;
        std::thread second_half([&] { sample_segments(segments, table, middle, end, curve); });
        sample_segments(segments, table, first, middle, curve);
        second_half.join();
    } else {
        sample_segments(segments, table, first, end, curve);
    }
}

// The lengths to control points first + 1 … : one addition per segment, in order.
void sum_lengths_from(std::size_t first, SampledCurve& curve)
{
    for (std::size_t s = first; s < curve.segment_length.size(); ++s)
        curve.length_to_point[s + 1] = curve.length_to_point[s] + curve.segment_length[s];
}

} // namespace

void sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment, SampledCurve& curve)
{
    curve.samples_per_segment = std::max(samples_per_segment, 1);
    if (segments.empty()) {
        curve.points.clear();
        curve.length_in_segment.clear();
        curve.segment_length.clear();
        curve.length_to_point.clear();
        return;
    }
    const std::size_t count = segments.size() * static_cast<std::size_t>(curve.samples_per_segment) + 1;
    curve.points.resize(count);
    curve.length_in_segment.resize(count);
    curve.segment_length.resize(segments.size());
    curve.length_to_point.resize(segments.size() + 1);
    sample_segments_on_cores(segments, curve.samples_per_segment, 0, segments.size(), curve);
    curve.points.back() = segments.back().end;
    curve.length_in_segment.back() = 0.0;
    curve.length_to_point[0] = 0.0;
    sum_lengths_from(0, curve);
}

void resample_segments(std::span<const HermiteSegment> segments, std::size_t first, std::size_t end,
                       SampledCurve& curve)
{
    assert(curve.segment_length.size() == segments.size() && first <= end && end <= segments.size());
    sample_segments_on_cores(segments, curve.samples_per_segment, first, end, curve);
    if (end == segments.size() && end > 0)
        curve.points.back() = segments.back().end;
    sum_lengths_from(first, curve);
}

} // namespace apcs
