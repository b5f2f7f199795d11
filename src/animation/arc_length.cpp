#include "apcs/animation/arc_length.h"

#include "apcs/base/parallel_work.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace apcs {

namespace {

// Composite Simpson over [0, u_end] with `intervals` (even) intervals.
double simpson(const HermiteSegment& curve, double u_end, int intervals)
{
    const double step = u_end / intervals;
    double sum = length(curve.derivative_at(0.0)) + length(curve.derivative_at(u_end));
    for (int i = 1; i < intervals; ++i)
        sum += (i % 2 == 1 ? 4.0 : 2.0) * length(curve.derivative_at(step * i));
    return sum * step / 3.0;
}

// The derivative basis (Eq. of hermite_basis_derivative) at the parameters each interval count adds:
// all n + 1 of u = i / n for the first count, the n / 2 odd ones for each doubling after. Every u is
// exact in binary, so these are the numbers derivative_at(step · i) would use.
struct NewParameters {
    std::array<std::vector<double>, 4> basis; // f1' … f4', one column each
};

std::vector<NewParameters> basis_of_each_count()
{
    std::vector<NewParameters> counts;
    for (int n = CurveArcLengths::first_simpson_intervals; n <= CurveArcLengths::most_simpson_intervals; n *= 2) {
        NewParameters added;
        const bool first = n == CurveArcLengths::first_simpson_intervals;
        for (int i = first ? 0 : 1; i <= n; i += first ? 1 : 2) {
            const HermiteBasis weights = hermite_basis_derivative(i == n ? 1.0 : (1.0 / n) * i);
            added.basis[0].push_back(weights.f1);
            added.basis[1].push_back(weights.f2);
            added.basis[2].push_back(weights.f3);
            added.basis[3].push_back(weights.f4);
        }
        counts.push_back(std::move(added));
    }
    return counts;
}

// A segment's Simpson sums as the interval count doubles: each count's speeds are the last count's
// and the new ones between them, found a column at a time from the tabulated basis (so that the
// compiler does several at once) as length(derivative_at(u)) finds them, to the bit, and summed in
// Simpson's order. Holds the speeds of the finest count: one per thread.
class SegmentArcLength {
public:
    SegmentArcLength()
        : m_counts(counts())
    {
        for (std::vector<double>* room : {&m_speeds, &m_finer, &m_new, &m_x, &m_y, &m_z})
            room->reserve(CurveArcLengths::most_simpson_intervals + 1);
    }

    // The length, and the interval count whose sum agreed with the one before it.
    std::pair<double, int> operator()(const HermiteSegment& curve)
    {
        int intervals = CurveArcLengths::first_simpson_intervals;
        speeds_at(curve, m_counts[0], m_speeds);
        double sum = sum_of_speeds(intervals);
        for (std::size_t level = 1; intervals < CurveArcLengths::most_simpson_intervals; ++level) {
            speeds_at(curve, m_counts[level], m_new);
            interleave();
            intervals *= 2;
            const double finer = sum_of_speeds(intervals);
            const bool converged = std::abs(finer - sum) <= 1e-10 * finer;
            sum = finer;
            if (converged)
                break;
        }
        return {sum, intervals};
    }

private:
    static const std::vector<NewParameters>& counts()
    {
        static const std::vector<NewParameters> tabulated = basis_of_each_count();
        return tabulated;
    }

    // HermiteSegment::apply on one coordinate: the same operations in the same order.
    static void coordinate(double start, double end, double start_tangent, double end_tangent,
                           const NewParameters& at, std::vector<double>& out)
    {
        const std::size_t count = at.basis[0].size();
        out.resize(count);
        for (std::size_t j = 0; j < count; ++j)
            out[j] = start * at.basis[0][j] + end * at.basis[1][j] + start_tangent * at.basis[2][j] +
                     end_tangent * at.basis[3][j];
    }

    void speeds_at(const HermiteSegment& curve, const NewParameters& at, std::vector<double>& out)
    {
        coordinate(curve.start.x, curve.end.x, curve.start_tangent.x, curve.end_tangent.x, at, m_x);
        coordinate(curve.start.y, curve.end.y, curve.start_tangent.y, curve.end_tangent.y, at, m_y);
        coordinate(curve.start.z, curve.end.z, curve.start_tangent.z, curve.end_tangent.z, at, m_z);
        out.resize(m_x.size());
        for (std::size_t j = 0; j < m_x.size(); ++j) // length(): sqrt(dot(v, v))
            out[j] = std::sqrt(m_x[j] * m_x[j] + m_y[j] * m_y[j] + m_z[j] * m_z[j]);
    }

    // m_speeds (count n + 1) and m_new (the n odd ones of 2n) into m_speeds (2n + 1).
    void interleave()
    {
        m_finer.clear();
        for (std::size_t i = 0; i < m_new.size(); ++i) {
            m_finer.push_back(m_speeds[i]);
            m_finer.push_back(m_new[i]);
        }
        m_finer.push_back(m_speeds.back());
        std::swap(m_speeds, m_finer);
    }

    double sum_of_speeds(int intervals) const
    {
        const double step = 1.0 / intervals;
        double sum = m_speeds.front() + m_speeds.back();
        for (std::size_t i = 1; i + 1 < m_speeds.size(); ++i)
            sum += (i % 2 == 1 ? 4.0 : 2.0) * m_speeds[i];
        return sum * step / 3.0;
    }

    const std::vector<NewParameters>& m_counts;
    std::vector<double> m_speeds;
    std::vector<double> m_finer;
    std::vector<double> m_new;
    std::vector<double> m_x;
    std::vector<double> m_y;
    std::vector<double> m_z;
};

} // namespace

void CurveArcLengths::measure(std::span<const HermiteSegment> segments)
{
    m_intervals.assign(segments.size(), 0);
    m_segment_length.assign(segments.size(), 0.0);
    m_cumulative.assign(segments.size() + 1, 0.0);
    measure_range(segments, 0, segments.size());
    add_up_from(0);
}

void CurveArcLengths::remeasure(std::span<const HermiteSegment> segments, const SegmentSplice& change)
{
    const bool fits = change.old_end() <= m_segment_length.size() &&
                      m_segment_length.size() - change.removed + change.inserted == segments.size();
    if (!fits)
        return measure(segments);
    splice_room(m_intervals, change);
    splice_room(m_segment_length, change);
    m_cumulative.resize(segments.size() + 1);
    measure_range(segments, change.first, change.new_end());
    add_up_from(change.first);
}

// A global change of 10^6 segments measures them on both cores; each segment alike either way.
void CurveArcLengths::measure_range(std::span<const HermiteSegment> segments, std::size_t first, std::size_t end)
{
    split_across_cores(end - first, 1024, [&](std::size_t from, std::size_t to) {
        SegmentArcLength measure;
        for (std::size_t k = first + from; k < first + to; ++k)
            std::tie(m_segment_length[k], m_intervals[k]) = measure(segments[k]);
    });
}

void CurveArcLengths::add_up_from(std::size_t first)
{
    m_cumulative[0] = 0.0;
    for (std::size_t k = first; k < m_segment_length.size(); ++k)
        m_cumulative[k + 1] = m_cumulative[k] + m_segment_length[k];
}

double CurveArcLengths::length_at(std::span<const HermiteSegment> segments, CurveParameter parameter) const
{
    if (segments.empty())
        return 0.0;
    const std::size_t segment = std::min(parameter.segment, segments.size() - 1);
    return m_cumulative[segment] + simpson(segments[segment], std::clamp(parameter.u, 0.0, 1.0), m_intervals[segment]);
}

CurveParameter CurveArcLengths::parameter_at(std::span<const HermiteSegment> segments, double arc_length) const
{
    if (segments.empty())
        return {};
    const double total = total_length();
    if (arc_length <= 0.0)
        return {0, 0.0};
    if (arc_length >= total)
        return {segments.size() - 1, 1.0};
    const double target = arc_length;
    // The first segment whose end lies at or beyond the target.
    const auto end = std::lower_bound(m_cumulative.begin() + 1, m_cumulative.end(), target);
    const std::size_t segment =
        std::min<std::size_t>(static_cast<std::size_t>(end - m_cumulative.begin()) - 1, segments.size() - 1);
    const double within = target - m_cumulative[segment];
    // Far below what a test or a picture can see, so that even steps come out even to 1e-9.
    const double tolerance = 1e-12 * total;
    double low = 0.0;
    double high = 1.0;
    // 200 halvings reach the resolution of a double long before; the bound only guarantees an end.
    for (int iteration = 0; iteration < 200 && high - low > 1e-15; ++iteration) {
        const double middle = (low + high) / 2.0;
        const double reached = simpson(segments[segment], middle, m_intervals[segment]);
        if (std::abs(reached - within) <= tolerance)
            return {segment, middle};
        (reached < within ? low : high) = middle;
    }
    return {segment, (low + high) / 2.0};
}

ArcLengthTable::ArcLengthTable(std::span<const HermiteSegment> segments)
    : m_segments(segments.begin(), segments.end())
{
    m_lengths.measure(m_segments);
}

Vec3 ArcLengthTable::point_at(CurveParameter parameter) const { return curve_point_at(m_segments, parameter); }

Vec3 curve_point_at(std::span<const HermiteSegment> segments, CurveParameter parameter)
{
    if (segments.empty())
        return {};
    const std::size_t segment = std::min(parameter.segment, segments.size() - 1);
    return segments[segment].point_at(std::clamp(parameter.u, 0.0, 1.0));
}

} // namespace apcs
