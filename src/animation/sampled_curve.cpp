#include "apcs/animation/sampled_curve.h"

#include "apcs/base/parallel_work.h"

#include <algorithm>
#include <array>
#include <cmath>

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
    // Summed as SegmentMeasure sums, from the segment's start: the same number to the bit.
    double within = 0.0;
    Vec3 previous = segments[segment].start;
    for (std::size_t j = 1; j <= i % per_segment; ++j) {
        const Vec3 point = segment_sample(segment, j);
        within += distance(previous, point);
        previous = point;
    }
    return length + within;
}

std::size_t SampledCurve::nearest_sample(double target) const { return NearestSamples(*this)(target).sample; }

// The chord lengths rise from sample to sample (distances are not negative, and a sum in floating
// point does not fall when a term does not), and a segment's last one is the length to the next
// control point: so the first sample at or beyond `target` lies in the segment whose end reaches it
// and whose start does not.
NearestSamples::Found NearestSamples::operator()(double target)
{
    const LargeArray<double>& to_point = m_curve.length_to_point;
    const auto reaching = std::lower_bound(to_point.begin(), to_point.end(), target);
    if (reaching == to_point.begin())
        return {0, 0.0};
    if (reaching == to_point.end())
        return {m_curve.sample_count() - 1, m_curve.total_length()};
    const auto segment = static_cast<std::size_t>(reaching - to_point.begin()) - 1;
    // Where the walk stopped, sample m_sample's chord length was the first to reach the last
    // target: one at or below the sample before it must walk the segment again.
    if (segment != m_segment || m_previous_chord >= target)
        start_segment(segment);
    while (m_chord < target)
        step();
    const std::size_t upper = segment * static_cast<std::size_t>(m_curve.samples_per_segment) + m_sample;
    const bool below_is_nearer = target - m_previous_chord <= m_chord - target;
    return below_is_nearer ? Found{upper - 1, m_previous_chord} : Found{upper, m_chord};
}

void NearestSamples::start_segment(std::size_t segment)
{
    m_segment = segment;
    m_sample = 0;
    m_point = m_curve.segments[segment].start;
    m_within = 0.0;
    m_chord = m_curve.length_to_point[segment];
    m_previous_chord = m_chord;
}

// The next sample, its chord length as chord_length finds it: the lengths to the control point
// and within the segment added, or the length to the next control point at the segment's end.
void NearestSamples::step()
{
    ++m_sample;
    m_previous_chord = m_chord;
    if (m_sample == static_cast<std::size_t>(m_curve.samples_per_segment)) {
        m_chord = m_curve.length_to_point[m_segment + 1];
        return;
    }
    const Vec3 point = m_curve.segment_sample(m_segment, m_sample);
    m_within += distance(m_point, point);
    m_point = point;
    m_chord = m_curve.length_to_point[m_segment] + m_within;
}

SampledCurve sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment)
{
    SampledCurve curve;
    curve.segments.assign(segments.begin(), segments.end());
    sample_curve(curve, samples_per_segment);
    return curve;
}

SegmentSampleColumns::SegmentSampleColumns(std::span<const HermiteBasis> basis)
    : x(basis.size())
    , y(basis.size())
    , z(basis.size())
{
    for (std::vector<double>& column : m_basis)
        column.reserve(basis.size());
    for (const HermiteBasis& weights : basis) {
        m_basis[0].push_back(weights.f1);
        m_basis[1].push_back(weights.f2);
        m_basis[2].push_back(weights.f3);
        m_basis[3].push_back(weights.f4);
    }
}

void SegmentSampleColumns::sample(const HermiteSegment& segment)
{
    sample_coordinate(segment.start.x, segment.end.x, segment.start_tangent.x, segment.end_tangent.x, x);
    sample_coordinate(segment.start.y, segment.end.y, segment.start_tangent.y, segment.end_tangent.y, y);
    sample_coordinate(segment.start.z, segment.end.z, segment.start_tangent.z, segment.end_tangent.z, z);
}

// One coordinate of the samples, as HermiteSegment::apply computes it.
void SegmentSampleColumns::sample_coordinate(double start, double end, double start_tangent, double end_tangent,
                                             std::vector<double>& out) const
{
    const std::size_t last = out.size() - 1;
    out[0] = start;
    for (std::size_t j = 1; j < last; ++j)
        out[j] = start * m_basis[0][j] + end * m_basis[1][j] + start_tangent * m_basis[2][j] +
                 end_tangent * m_basis[3][j];
    out[last] = end;
}

SegmentMeasure::SegmentMeasure(std::span<const HermiteBasis> basis)
    : m_samples(basis)
{
}

// Distances a column at a time; only the sum runs one sample after another, in order (as
// chord_length sums).
double SegmentMeasure::operator()(const HermiteSegment& segment)
{
    m_samples.sample(segment);
    std::vector<double>& x = m_samples.x;
    const std::vector<double>& y = m_samples.y;
    const std::vector<double>& z = m_samples.z;
    // distance(previous, point) is the length of point − previous; x then holds the distances.
    for (std::size_t j = 1; j < x.size(); ++j) {
        const double dx = x[j] - x[j - 1];
        const double dy = y[j] - y[j - 1];
        const double dz = z[j] - z[j - 1];
        x[j - 1] = std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    double length = 0.0;
    for (std::size_t j = 0; j + 1 < x.size(); ++j)
        length += x[j];
    return length;
}

void add_up_lengths(SampledCurve& curve, std::size_t first, std::size_t end)
{
    for (std::size_t s = first; s < std::min(end, curve.segment_length.size()); ++s)
        curve.length_to_point[s + 1] = curve.length_to_point[s] + curve.segment_length[s];
}

void sample_curve(SampledCurve& curve, int samples_per_segment)
{
    curve.samples_per_segment = std::max(samples_per_segment, 1);
    curve.basis = hermite_basis_table(curve.samples_per_segment);
    curve.segment_length.resize(curve.segments.size());
    curve.length_to_point.resize(curve.segments.empty() ? 0 : curve.segments.size() + 1);
    if (curve.segments.empty())
        return;
    // A long path (a session's 10^6 control points: 3.2·10^7 samples) is measured on two cores;
    // each segment alike either way, so the lengths are the same to the bit.
    split_across_cores(curve.segments.size(), 4096, [&](std::size_t first, std::size_t end) {
        SegmentMeasure measure(curve.basis);
        for (std::size_t s = first; s < end; ++s)
            curve.segment_length[s] = measure(curve.segments[s]);
    });
    curve.length_to_point[0] = 0.0;
    add_up_lengths(curve, 0);
}

} // namespace apcs
