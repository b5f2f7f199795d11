#pragma once

#include "apcs/animation/hermite.h"
#include "apcs/animation/path_change.h"

#include <algorithm>
#include <span>
#include <vector>

namespace apcs {

// A position on a piecewise curve: segment index and parameter u in [0, 1] within it.
struct CurveParameter {
    std::size_t segment = 0;
    double u = 0.0;
};

// Arc length A(u) = ∫‖P'(u)‖du of a piecewise Hermite curve (slides of seed 004): composite
// Simpson per segment, a cumulative table over segments, and the parameter for a given length by
// bisection to 1e-9·L. Each segment's interval count doubles from 32 until two successive sums
// agree to 1e-10 of the length (at most 8192), because a tightly bent segment needs many more
// intervals than a flat one.
//
// Kept beside the curve's segments, which it does not hold: every call takes the segments it was
// measured on. A change to some segments (a SegmentSplice) measures those again and adds up the
// lengths after them, so that exact spacing stays interactive on a path of 10^6 control points;
// the numbers are those of measuring afresh, to the bit (each segment is measured alike either way,
// and the sums are added in the same order).
class CurveArcLengths {
public:
    static constexpr int first_simpson_intervals = 32;
    static constexpr int most_simpson_intervals = 8192;

    // Every segment measured (on both cores for a long curve).
    void measure(std::span<const HermiteSegment> segments);
    // `segments` is the curve after `change`; the curve before it was the one last measured.
    void remeasure(std::span<const HermiteSegment> segments, const SegmentSplice& change);
    // The same in steps (a first picture, refined after): the table is made to fit the curve after
    // `change` and the segments it made are only marked to be measured; a change marked before and
    // not yet measured is kept (the two ranges become one). Until measure_pending() has measured
    // them all, the lengths are those of no curve: pending() says so.
    void mark_changed(std::span<const HermiteSegment> segments, const SegmentSplice& change);
    // Every segment marked (the table made to fit `segments`).
    void mark_all(std::span<const HermiteSegment> segments);
    bool pending() const { return m_pending_first < m_pending_end || m_sum_from < m_cumulative.size(); }
    std::size_t segments_pending() const { return m_pending_end - m_pending_first; }
    // Measures up to `most_segments` of the marked segments (in order), and adds the lengths up once
    // none is left. The numbers are then remeasure's, to the bit: each segment is measured alike.
    void measure_pending(std::span<const HermiteSegment> segments, std::size_t most_segments);

    std::size_t segment_count() const { return m_segment_length.size(); }
    double total_length() const { return m_cumulative.empty() ? 0.0 : m_cumulative.back(); }
    // Arc length from the curve's start to the start of segment k (k = segment count: the end).
    double length_to_segment_start(std::size_t segment) const
    {
        return m_cumulative.empty() ? 0.0 : m_cumulative[std::min(segment, m_cumulative.size() - 1)];
    }
    double length_at(std::span<const HermiteSegment> segments, CurveParameter parameter) const;
    // The parameter whose arc length from the start is `arc_length`, clamped to [0, L], to 1e-12 of
    // L: Newton's steps on the segment it falls in, inside a bracket that halves when a step leaves it.
    CurveParameter parameter_at(std::span<const HermiteSegment> segments, double arc_length) const;

private:
    void measure_range(std::span<const HermiteSegment> segments, std::size_t first, std::size_t end);
    void add_up_from(std::size_t first);

    LargeArray<int> m_intervals; // Simpson intervals chosen for each segment
    LargeArray<double> m_segment_length;
    // m_cumulative[k] = length of segments 0 … k−1; size = segments + 1.
    LargeArray<double> m_cumulative;
    // mark_changed: segments m_pending_first … m_pending_end − 1 are to be measured, the sums from
    // m_cumulative[m_sum_from + 1] on to be added up (m_sum_from = size: none).
    std::size_t m_pending_first = 0;
    std::size_t m_pending_end = 0;
    std::size_t m_sum_from = 1;
};

// The arc lengths of a copy of `segments`, so that the table outlives its argument.
class ArcLengthTable {
public:
    static constexpr int first_simpson_intervals = CurveArcLengths::first_simpson_intervals;
    static constexpr int most_simpson_intervals = CurveArcLengths::most_simpson_intervals;

    explicit ArcLengthTable(std::span<const HermiteSegment> segments);

    double total_length() const { return m_lengths.total_length(); }
    double length_to_segment_start(std::size_t segment) const { return m_lengths.length_to_segment_start(segment); }
    double length_at(CurveParameter parameter) const { return m_lengths.length_at(m_segments, parameter); }
    CurveParameter parameter_at(double arc_length) const { return m_lengths.parameter_at(m_segments, arc_length); }
    Vec3 point_at(CurveParameter parameter) const;

private:
    std::vector<HermiteSegment> m_segments;
    CurveArcLengths m_lengths;
};

// The point of `segments` at `parameter` (segment and u clamped into the curve).
Vec3 curve_point_at(std::span<const HermiteSegment> segments, CurveParameter parameter);

// ∫ ‖P'(u)‖ du of `segment` from u = from to u = to by one five-point Gauss–Legendre sum: its arc
// length there, to the accuracy of a speed polynomial of degree 9.
double speed_integral(const HermiteSegment& segment, double from, double to);

// The parameter u of `segment` halfway along it by arc length, at a cost that never depends on the
// segment (16 panels of 5-point Gauss–Legendre, then Newton's steps inside one panel): a waypoint
// inserted on a segment a millionth of a pixel long costs what one on a long one does. Within
// 1e-12 of the length of the Simpson sums above on a smooth segment; 0.5 on a segment of no length.
double halfway_parameter(const HermiteSegment& segment);

} // namespace apcs
