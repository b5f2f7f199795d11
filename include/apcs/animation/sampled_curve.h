#pragma once

#include "apcs/animation/hermite.h"

#include <array>
#include <span>
#include <vector>

namespace apcs {

// The Hermite basis tabulated at u = j / samples_per_segment, j = 0 … samples_per_segment
// (the thesis' Cal_Hermite_Basis), so that sampling a segment costs no polynomial evaluation.
std::vector<HermiteBasis> hermite_basis_table(int samples_per_segment);

// A KB curve's segments sampled at `samples_per_segment` points each: N = segments · samples_per_segment
// intervals, N + 1 samples, control point k at sample k · samples_per_segment.
//
// Samples are computed when asked for, never held: a path of 10^6 control points has 3.2·10^7 of
// them, 1 GB to write at every key of a global change. What is kept is each segment's chord length
// (the length of the polyline through its samples) and the lengths to the control points, so that a
// change to a few segments measures those again and adds up one number per segment.
struct SampledCurve {
    HermiteSegments segments;
    // Each segment's chord length, and the chord length from the start to control point k
    // (k = 0 … segments): 0 first, the whole length L last.
    LargeArray<double> segment_length;
    LargeArray<double> length_to_point;
    int samples_per_segment = 1;
    std::vector<HermiteBasis> basis; // hermite_basis_table(samples_per_segment)

    // N + 1, or 0 for a curve of no segments.
    std::size_t sample_count() const;
    // Sample j (0 … samples_per_segment) of segment s: its start and end are the control points
    // themselves, exactly, not a rounded evaluation.
    Vec3 segment_sample(std::size_t segment, std::size_t j) const;
    // Sample i (i < sample_count()).
    Vec3 sample(std::size_t i) const;
    // Every sample, in order (for printing; a long path's are not held otherwise).
    std::vector<Vec3> samples() const;
    double total_length() const { return length_to_point.empty() ? 0.0 : length_to_point.back(); }
    // The chord length from the curve's start to sample i (i < sample_count()).
    double chord_length(std::size_t i) const;
    // The sample whose chord length is nearest to `target`, the earlier of two equally near (the
    // thesis' Decide_Show_Inbetween); the first or last sample for a target outside the curve.
    // Costs log2(segments) comparisons and up to samples_per_segment samples; NearestSamples finds
    // a run of increasing targets' samples at once.
    std::size_t nearest_sample(double target) const;
};

// SampledCurve::nearest_sample for one target after another, and the chord length of the sample
// found (chord_length's, to the bit). The segment holding a target is found among the lengths to
// the control points; its samples are then walked from its start, summed as chord_length sums
// them. A target in the segment of the one before goes on from where that one stopped, so that
// M increasing targets (a path's in-betweens, more of them than samples or fewer) cost
// O(N + M·log2 segments) for N samples, not M·log2 N·samples_per_segment; a target below the
// sample before the last one found walks its segment again from the start. Holds a
// reference to `curve`, which must outlive it unchanged.
class NearestSamples {
public:
    struct Found {
        std::size_t sample = 0;
        double chord_length = 0.0;
    };

    explicit NearestSamples(const SampledCurve& curve)
        : m_curve(curve)
    {
    }
    Found operator()(double target);

private:
    void start_segment(std::size_t segment);
    void step();

    const SampledCurve& m_curve;
    // The walk: sample m_sample of segment m_segment (m_sample = 0 … samples_per_segment), its
    // point, the chord length within the segment summed so far, and the chord lengths from the
    // curve's start to it and to the sample before it.
    std::size_t m_segment = static_cast<std::size_t>(-1);
    std::size_t m_sample = 0;
    Vec3 m_point;
    double m_within = 0.0;
    double m_chord = 0.0;
    double m_previous_chord = 0.0;
};

// A curve of a copy of `segments`; samples_per_segment is clamped to at least 1.
SampledCurve sample_curve(std::span<const HermiteSegment> segments, int samples_per_segment);
// Measures `curve.segments` (set by the caller, arrays' room kept) at samples_per_segment.
void sample_curve(SampledCurve& curve, int samples_per_segment);
// One segment's samples 0 … samples_per_segment, a coordinate at a time (columns), as
// SampledCurve::segment_sample computes each: the same operations in the same order, the same
// bits, so that the compiler does several samples in one instruction; the ends are the control
// points themselves. Holds the basis in columns and room for one segment: one per thread.
class SegmentSampleColumns {
public:
    explicit SegmentSampleColumns(std::span<const HermiteBasis> basis);
    void sample(const HermiteSegment& segment);

    // Sample j is (x[j], y[j], z[j]) after sample(); a caller may write over them.
    std::vector<double> x;
    std::vector<double> y;
    std::vector<double> z;

private:
    void sample_coordinate(double start, double end, double start_tangent, double end_tangent,
                           std::vector<double>& out) const;

    std::array<std::vector<double>, 4> m_basis; // f1 … f4 of every sample
};

// The chord length of a segment's samples, summed in order (as SampledCurve::chord_length sums):
// what sample_curve keeps in segment_length, to the bit. One per thread.
class SegmentMeasure {
public:
    explicit SegmentMeasure(std::span<const HermiteBasis> basis);
    double operator()(const HermiteSegment& segment);

private:
    SegmentSampleColumns m_samples;
};

// After segment_length changed from segment `first` on: the lengths to the control points after it.
// Those of segments first … end − 1 alone, the lengths before them current (a curve made in steps).
void add_up_lengths(SampledCurve& curve, std::size_t first, std::size_t end = static_cast<std::size_t>(-1));

} // namespace apcs
