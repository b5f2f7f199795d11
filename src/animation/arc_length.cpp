#include "apcs/animation/arc_length.h"

#include <algorithm>

namespace apcs {

ArcLengthTable::ArcLengthTable(std::span<const HermiteSegment> segments)
    : m_segments(segments.begin(), segments.end())
{
    m_cumulative.reserve(m_segments.size() + 1);
    m_intervals.reserve(m_segments.size());
    m_cumulative.push_back(0.0);
    for (std::size_t k = 0; k < m_segments.size(); ++k) {
        int intervals = first_simpson_intervals;
        double sum = simpson(k, 1.0, intervals);
        while (intervals < most_simpson_intervals) {
            const double finer = simpson(k, 1.0, intervals * 2);
            intervals *= 2;
            const bool converged = std::abs(finer - sum) <= 1e-10 * finer;
            sum = finer;
            if (converged)
                break;
        }
        m_intervals.push_back(intervals);
        m_cumulative.push_back(m_cumulative.back() + sum);
    }
}

double ArcLengthTable::simpson(std::size_t segment, double u_end, int intervals) const
{
    const HermiteSegment& curve = m_segments[segment];
    const double step = u_end / intervals;
    double sum = length(curve.derivative_at(0.0)) + length(curve.derivative_at(u_end));
    for (int i = 1; i < intervals; ++i)
        sum += (i % 2 == 1 ? 4.0 : 2.0) * length(curve.derivative_at(step * i));
    return sum * step / 3.0;
}

double ArcLengthTable::segment_length(std::size_t segment, double u_end) const
{
    return simpson(segment, u_end, m_intervals[segment]);
}

double ArcLengthTable::length_at(CurveParameter parameter) const
{
    if (m_segments.empty())
        return 0.0;
    const std::size_t segment = std::min(parameter.segment, m_segments.size() - 1);
    return m_cumulative[segment] + segment_length(segment, std::clamp(parameter.u, 0.0, 1.0));
}

CurveParameter ArcLengthTable::parameter_at(double arc_length) const
{
    if (m_segments.empty())
        return {};
    const double total = total_length();
    if (arc_length <= 0.0)
        return {0, 0.0};
    if (arc_length >= total)
        return {m_segments.size() - 1, 1.0};
    const double target = arc_length;
    // The first segment whose end lies at or beyond the target.
    const auto end = std::lower_bound(m_cumulative.begin() + 1, m_cumulative.end(), target);
    const std::size_t segment = std::min<std::size_t>(static_cast<std::size_t>(end - m_cumulative.begin()) - 1,
                                                      m_segments.size() - 1);
    const double within = target - m_cumulative[segment];
    // Far below what a test or a picture can see, so that even steps come out even to 1e-9.
    const double tolerance = 1e-12 * total;
    double low = 0.0;
    double high = 1.0;
    // 200 halvings reach the resolution of a double long before; the bound only guarantees an end.
    for (int iteration = 0; iteration < 200 && high - low > 1e-15; ++iteration) {
        const double middle = (low + high) / 2.0;
        const double reached = segment_length(segment, middle);
        if (std::abs(reached - within) <= tolerance)
            return {segment, middle};
        (reached < within ? low : high) = middle;
    }
    return {segment, (low + high) / 2.0};
}

Vec3 ArcLengthTable::point_at(CurveParameter parameter) const
{
    if (m_segments.empty())
        return {};
    const std::size_t segment = std::min(parameter.segment, m_segments.size() - 1);
    return m_segments[segment].point_at(std::clamp(parameter.u, 0.0, 1.0));
}

} // namespace apcs
