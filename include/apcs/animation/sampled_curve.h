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
struct SampledCurve {
    std::vector<Vec3> points;
    // Cumulative chord length: chord_length[0] = 0, chord_length.back() = L (world units).
    std::vector<double> chord_length;
    int samples_per_segment = 1;

    double total_length() const { return chord_length.empty() ? 0.0 : chord_length.back(); }
};

// samples_per_segment is clamped to at least 1.
SampledCurve sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment);
// The same into `curve`, whose arrays keep their room.
void sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment, SampledCurve& curve);

} // namespace apcs
