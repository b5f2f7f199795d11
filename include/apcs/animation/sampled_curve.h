#pragma once

#include "apcs/animation/hermite.h"

#include <span>
#include <vector>

namespace apcs {

// The Hermite basis tabulated at u = j / samples_per_segment, j = 0 … samples_per_segment
// (the thesis' Cal_Hermite_Basis), so that sampling a segment costs no polynomial evaluation.
std::vector<HermiteBasis> hermite_basis_table(int samples_per_segment);

// A KB curve sampled at `samples_per_segment` points per segment: N = segments · samples_per_segment
// intervals, N + 1 points, with control point k at index k · samples_per_segment.
//
// The chord length (the polyline's length from the start) is kept in two levels, each segment's
// own and the lengths to the control points, so that a change to a few segments of a long path
// measures those segments again and adds up one number per segment, not one per sample.
struct SampledCurve {
    std::vector<Vec3> points;
    // Chord length from the first sample of sample i's segment (its control point) to sample i:
    // 0 at every control point.
    std::vector<double> length_in_segment;
    // Each segment's chord length, and the chord length from the start to control point k
    // (k = 0 … segments): 0 first, the whole length L last.
    std::vector<double> segment_length;
    std::vector<double> length_to_point;
    int samples_per_segment = 1;

    double total_length() const { return length_to_point.empty() ? 0.0 : length_to_point.back(); }
    // The chord length from the curve's start to sample i (i < points.size()).
    double chord_length(std::size_t sample) const
    {
        return length_to_point[sample / static_cast<std::size_t>(samples_per_segment)] + length_in_segment[sample];
    }
    // The sample whose chord length is nearest to `target`, the earlier of two equally near (the
    // thesis' Decide_Show_Inbetween); the first or last sample for a target outside the curve.
    std::size_t nearest_sample(double target) const;
};

// samples_per_segment is clamped to at least 1.
SampledCurve sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment);
// The same into `curve`, whose arrays keep their room.
void sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment, SampledCurve& curve);
// Segments first … end − 1 of a curve sampled from `segments` (same count, same samples per
// segment) changed: their samples and lengths are made again, and the lengths to the control points
// after them. The curve is then the one sample_curve makes, to the bit.
void resample_segments(std::span<const HermiteSegment> segments, std::size_t first, std::size_t end,
                       SampledCurve& curve);

} // namespace apcs
