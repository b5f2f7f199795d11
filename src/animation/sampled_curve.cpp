#include "apcs/animation/sampled_curve.h"

#include <algorithm>

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
    const std::size_t count = segments.size() * static_cast<std::size_t>(curve.samples_per_segment) + 1;
    curve.points.reserve(count);
    curve.chord_length.reserve(count);
    curve.points.push_back(segments.front().start);
    curve.chord_length.push_back(0.0);
    for (const HermiteSegment& segment : segments) {
        for (std::size_t j = 1; j < table.size(); ++j) {
            // The last sample is the end control point itself, exactly, not a rounded evaluation.
            const Vec3 point = j + 1 == table.size() ? segment.end : segment.apply(table[j]);
            curve.chord_length.push_back(curve.chord_length.back() + distance(curve.points.back(), point));
            curve.points.push_back(point);
        }
    }
}

} // namespace apcs
