#include "apcs/animation/sampled_curve.h"

#include <algorithm>
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

SampledCurve sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment)
{
    SampledCurve curve;
    sample_curve(segments, samples_per_segment, curve);
    return curve;
}

void sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment, SampledCurve& curve)
{
    curve.samples_per_segment = std::max(samples_per_segment, 1);
    curve.points.clear();
    curve.chord_length.clear();
    if (segments.empty())
        return;
    const std::vector<HermiteBasis> table = hermite_basis_table(curve.samples_per_segment);
    const std::size_t per_segment = static_cast<std::size_t>(curve.samples_per_segment);
    const std::size_t count = segments.size() * per_segment + 1;
    curve.points.resize(count);
    curve.chord_length.resize(count);
    curve.points[0] = segments.front().start;
    curve.chord_length[0] = 0.0;
    // Segments first … end − 1: their samples, and in chord_length each sample's distance from
    // the one before (a segment starts where the one before ended: the same control point).
    const auto sample_segments = [&](std::size_t first, std::size_t end) {
        Vec3 previous = segments[first].start;
        for (std::size_t s = first; s < end; ++s) {
            const HermiteSegment& segment = segments[s];
            for (std::size_t j = 1; j < table.size(); ++j) {
                // The last sample is the end control point itself, exactly, not a rounded evaluation.
                const Vec3 point = j + 1 == table.size() ? segment.end : segment.apply(table[j]);
                const std::size_t index = s * per_segment + j;
                curve.points[index] = point;
                curve.chord_length[index] = distance(previous, point);
                previous = point;
            }
        }
    };
    // A long path (a session's 10^5 control points: 3.2 million samples) is sampled on two cores;
    // each sample is computed alike either way, and the lengths are summed in order below, so the
    // curve is the same to the bit.
    constexpr std::size_t segments_worth_a_thread = 4096;
    if (segments.size() >= 2 * segments_worth_a_thread && std::thread::hardware_concurrency() > 1) {
        const std::size_t middle = segments.size() / 2;
        std::thread second_half(sample_segments, middle, segments.size());
        sample_segments(0, middle);
        second_half.join();
    } else {
        sample_segments(0, segments.size());
    }
    for (std::size_t i = 1; i < count; ++i)
        curve.chord_length[i] += curve.chord_length[i - 1];
}

} // namespace apcs
