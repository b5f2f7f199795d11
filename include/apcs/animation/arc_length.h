#pragma once

#include "apcs/animation/hermite.h"

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
// intervals than a flat one. The table keeps a copy of the segments, so it outlives its argument.
class ArcLengthTable {
public:
    static constexpr int first_simpson_intervals = 32;
    static constexpr int most_simpson_intervals = 8192;

    explicit ArcLengthTable(std::span<const HermiteSegment> segments);

    double total_length() const { return m_cumulative.empty() ? 0.0 : m_cumulative.back(); }
    // Arc length from the curve's start to the start of segment k (k = segment count: the end).
    double length_to_segment_start(std::size_t segment) const
    {
        return m_cumulative[std::min(segment, m_cumulative.size() - 1)];
    }
    // Arc length from the curve's start to the given parameter.
    double length_at(CurveParameter parameter) const;
    // The parameter whose arc length from the start is `arc_length`, clamped to [0, L].
    CurveParameter parameter_at(double arc_length) const;
    Vec3 point_at(CurveParameter parameter) const;

private:
    double simpson(std::size_t segment, double u_end, int intervals) const;
    double segment_length(std::size_t segment, double u_end) const;

    std::vector<HermiteSegment> m_segments;
    std::vector<int> m_intervals; // Simpson intervals chosen for each segment
    // m_cumulative[k] = length of segments 0 … k−1; size = segments + 1.
    std::vector<double> m_cumulative;
};

} // namespace apcs
