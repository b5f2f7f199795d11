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

std::size_t SampledCurve::sample_count() const
{
    return segments.empty() ? 0 : segments.size() * static_cast<std::size_t>(samples_per_segment) + 1;
}

Vec3 SampledCurve::segment_sample(std::size_t segment, std::size_t j) const
{
    const HermiteSegment& shape = segments[segment];
    if (j == 0)
        return shape.start;
    return j + 1 == basis.size() ? shape.end : shape.apply(basis[j]);
}

Vec3 SampledCurve::sample(std::size_t i) const
{
    const std::size_t per_segment = static_cast<std::size_t>(samples_per_segment);
    const std::size_t segment = i / per_segment;
    return segment == segments.size() ? segments.back().end : segment_sample(segment, i % per_segment);
}

std::vector<Vec3> SampledCurve::samples() const
{
    std::vector<Vec3> all;
    all.reserve(sample_count());
    for (std::size_t i = 0; i < sample_count(); ++i)
        all.push_back(sample(i));
    return all;
}

double SampledCurve::chord_length(std::size_t i) const
{
    const std::size_t per_segment = static_cast<std::size_t>(samples_per_segment);
    const std::size_t segment = i / per_segment;
    double length = length_to_point[segment];
    if (segment == segments.size())
        return length;
    // Summed as measure_segments sums, from the segment's start: the same number to the bit.
    double within = 0.0;
    Vec3 previous = segments[segment].start;
    for (std::size_t j = 1; j <= i % per_segment; ++j) {
        const Vec3 point = segment_sample(segment, j);
        within += distance(previous, point);
        previous = point;
    }
    return length + within;
}

std::size_t SampledCurve::nearest_sample(double target) const
{
    const auto indices = std::views::iota(std::size_t{0}, sample_count());
    const auto above = std::ranges::partition_point(indices, [&](std::size_t i) { return chord_length(i) < target; });
    if (above == indices.begin())
        return 0;
    if (above == indices.end())
        return sample_count() - 1;
    const std::size_t upper = *above;
    const bool below_is_nearer = target - chord_length(upper - 1) <= chord_length(upper) - target;
    return below_is_nearer ? upper - 1 : upper;
}

SampledCurve sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment)
{
    SampledCurve curve;
    curve.segments.assign(segments.begin(), segments.end());
    sample_curve(curve, samples_per_segment);
    return curve;
}

namespace {

// Measures segments first … end − 1: each sample's distance from the one before, summed along
// the segment. Segments are independent of each other.
void measure_segments(SampledCurve& curve, std::size_t first, std::size_t end)
{
    const std::size_t per_segment = static_cast<std::size_t>(curve.samples_per_segment);
    for (std::size_t s = first; s < end; ++s) {
        Vec3 previous = curve.segments[s].start;
        double length = 0.0;
        for (std::size_t j = 1; j <= per_segment; ++j) {
            const Vec3 point = curve.segment_sample(s, j);
            length += distance(previous, point);
            previous = point;
        }
        curve.segment_length[s] = length;
    }
}

// A long path (a session's 10^6 control points: 3.2·10^7 samples) is measured on two cores; each
// segment is measured alike either way, so the lengths are the same to the bit.
void measure_segments_on_cores(SampledCurve& curve, std::size_t first, std::size_t end)
{
    constexpr std::size_t segments_worth_a_thread = 4096;
    if (end - first >= 2 * segments_worth_a_thread && std::thread::hardware_concurrency() > 1) {
        const std::size_t middle = first + (end - first) / 2;
        std::thread second_half([&] { measure_segments(curve, middle, end); });
        measure_segments(curve, first, middle);
        second_half.join();
    } else {
        measure_segments(curve, first, end);
    }
}

// The lengths to control points first + 1 … : one addition per segment, in order.
void sum_lengths_from(std::size_t first, SampledCurve& curve)
{
    for (std::size_t s = first; s < curve.segment_length.size(); ++s)
        curve.length_to_point[s + 1] = curve.length_to_point[s] + curve.segment_length[s];
}

} // namespace

void sample_curve(SampledCurve& curve, int samples_per_segment)
{
    curve.samples_per_segment = std::max(samples_per_segment, 1);
    curve.basis = hermite_basis_table(curve.samples_per_segment);
    curve.segment_length.resize(curve.segments.size());
    curve.length_to_point.resize(curve.segments.empty() ? 0 : curve.segments.size() + 1);
    if (curve.segments.empty())
        return;
    curve.length_to_point[0] = 0.0;
    measure_segments_on_cores(curve, 0, curve.segments.size());
    sum_lengths_from(0, curve);
}

void remeasure_segments(SampledCurve& curve, std::size_t first, std::size_t end)
{
    assert(curve.segment_length.size() == curve.segments.size() && first <= end && end <= curve.segments.size());
    measure_segments_on_cores(curve, first, end);
    sum_lengths_from(first, curve);
}

} // namespace apcs
