#include "apcs/animation/arc_length.h"

#include "apcs/base/parallel_work.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

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
// exact in binary, so these are the numbers derivative_at(step · i) would use. `order` lists where
// speed i of the count's Simpson sum (i = 0 … n) is kept: a segment's speeds are stored as they are
// found, the first count's and then each doubling's new ones after them.
struct NewParameters {
    std::array<std::vector<double>, 4> basis; // f1' … f4', one column each
    std::vector<std::uint32_t> order;
};

std::vector<NewParameters> basis_of_each_count()
{
    std::vector<NewParameters> counts;
    std::uint32_t stored = 0;
    for (int n = CurveArcLengths::first_simpson_intervals; n <= CurveArcLengths::most_simpson_intervals; n *= 2) {
        NewParameters added;
        const bool first = n == CurveArcLengths::first_simpson_intervals;
        for (int i = 0; i <= n; ++i) {
            const bool new_here = first || i % 2 == 1;
            if (!new_here) {
                added.order.push_back(counts.back().order[static_cast<std::size_t>(i / 2)]);
                continue;
            }
            const HermiteBasis weights = hermite_basis_derivative(i == n ? 1.0 : (1.0 / n) * i);
            added.basis[0].push_back(weights.f1);
            added.basis[1].push_back(weights.f2);
            added.basis[2].push_back(weights.f3);
            added.basis[3].push_back(weights.f4);
            added.order.push_back(stored++);
        }
        counts.push_back(std::move(added));
    }
    return counts;
}

// On x86-64 Linux a second copy of a function for processors with AVX2, chosen when the program
// loads: twice the numbers in one instruction. The operations and their order are the same, and
// no multiply and add are fused (the build contracts none), so the copies give the same bits.
#if defined(__x86_64__) && defined(__linux__)
#define APCS_ALSO_FOR_AVX2 __attribute__((target_clones("avx2", "default")))
#else
#define APCS_ALSO_FOR_AVX2
#endif

// length(curve.derivative_at(u)) at the parameters `at` adds, into `out`: HermiteSegment::apply and
// length() with the same operations in the same order (the same bits), several parameters at once.
// Its square roots are the largest part of an exact-spacing global key (docs/PERFORMANCE.md, 9b).
APCS_ALSO_FOR_AVX2 void speeds_at(const HermiteSegment& curve, const NewParameters& at, double* out)
{
    const double* const f1 = at.basis[0].data();
    const double* const f2 = at.basis[1].data();
    const double* const f3 = at.basis[2].data();
    const double* const f4 = at.basis[3].data();
    const Vec3 start = curve.start;
    const Vec3 end = curve.end;
    const Vec3 start_tangent = curve.start_tangent;
    const Vec3 end_tangent = curve.end_tangent;
    const std::size_t count = at.basis[0].size();
    for (std::size_t j = 0; j < count; ++j) {
        const double x = start.x * f1[j] + end.x * f2[j] + start_tangent.x * f3[j] + end_tangent.x * f4[j];
        const double y = start.y * f1[j] + end.y * f2[j] + start_tangent.y * f3[j] + end_tangent.y * f4[j];
        const double z = start.z * f1[j] + end.z * f2[j] + start_tangent.z * f3[j] + end_tangent.z * f4[j];
        out[j] = std::sqrt(x * x + y * y + z * z);
    }
}

// Sum of `values` in four running sums (several at once): not Simpson's order, only an estimate.
double estimate_sum(std::span<const double> values)
{
    std::array<double, 4> partial{};
    std::size_t i = 0;
    for (; i + 4 <= values.size(); i += 4)
        for (std::size_t lane = 0; lane < 4; ++lane)
            partial[lane] += values[i + lane];
    for (; i < values.size(); ++i)
        partial[0] += values[i];
    return (partial[0] + partial[1]) + (partial[2] + partial[3]);
}

// A segment's Simpson sums as the interval count doubles: each count's speeds are the last count's
// and the new ones between them, found a column at a time from the tabulated basis (so that the
// compiler does several at once) as length(derivative_at(u)) finds them, to the bit. Holds the
// speeds of the finest count: one per thread.
//
// Summing a count's speeds in Simpson's order is one addition after another (each waits for the
// last): that, done afresh at every count, was most of the time. So whether two counts agree is
// decided on estimates (each count's new speeds summed once, several at a time), and the sums are
// added in Simpson's order only where the estimate cannot decide — the speeds are non-negative, so
// an estimate and Simpson's sum of m terms both lie within m·2^-53 of the true sum, relative
// (Higham, "Accuracy and Stability of Numerical Algorithms", 4.2) — and once for the count that
// converged, whose sum is the length. The length and the count are those of summing every count in
// order, to the bit.
class SegmentArcLength {
public:
    SegmentArcLength()
        : m_counts(counts())
    {
        m_speeds.reserve(CurveArcLengths::most_simpson_intervals + 1);
    }

    // Where a segment's sums agreed: the count (its index in the doublings and its intervals), and
    // Simpson's sum of it if it was summed on the way (else simpson_sum(level) gives it).
    struct Converged {
        std::size_t level = 0;
        int intervals = 0;
        bool summed = false;
        double sum = 0.0;
    };

    // The speeds of `curve`, kept until the next call, up to the count whose sum agreed with the
    // one before it (or the finest).
    Converged converge(const HermiteSegment& curve)
    {
        m_speeds.clear();
        add_speeds(curve, m_counts[0]);
        int intervals = CurveArcLengths::first_simpson_intervals;
        const double ends = m_speeds.front() + m_speeds.back();
        double odd = 0.0;
        double even = 0.0;
        for (int i = 1; i < intervals; ++i)
            (i % 2 == 1 ? odd : even) += m_speeds[static_cast<std::size_t>(i)];
        Estimate coarser{(ends + 4.0 * odd + 2.0 * even) / intervals / 3.0, 0.0, false};
        double inside = odd + even; // the speeds of the count reached, but its ends
        std::size_t level = 1;
        for (; intervals < CurveArcLengths::most_simpson_intervals; ++level) {
            const std::size_t first_new = m_speeds.size();
            add_speeds(curve, m_counts[level]);
            intervals *= 2;
            const double added = estimate_sum(std::span(m_speeds).subspan(first_new));
            Estimate finer{(ends + 4.0 * added + 2.0 * inside) / intervals / 3.0, 0.0, false};
            inside += added;
            const bool converged = agree(coarser, finer, level);
            coarser = finer;
            if (converged)
                break;
        }
        if (level == m_counts.size())
            --level;
        return {level, intervals, coarser.exact, coarser.sum};
    }

    // Simpson's sum of the count at `level` of the speeds kept, added in order.
    double simpson_sum(std::size_t level) const
    {
        const std::vector<std::uint32_t>& order = m_counts[level].order;
        const std::size_t intervals = order.size() - 1;
        const double step = 1.0 / static_cast<double>(intervals);
        double sum = m_speeds[order.front()] + m_speeds[order.back()];
        for (std::size_t i = 1; i + 1 < order.size(); i += 2) {
            sum += 4.0 * m_speeds[order[i]];
            if (i + 2 < order.size())
                sum += 2.0 * m_speeds[order[i + 1]];
        }
        return sum * step / 3.0;
    }

    // simpson_sum(level) of two segments' speeds, added side by side: the two sums do not wait for
    // each other, so the processor does both at the cost of one.
    static std::pair<double, double> simpson_sums(const SegmentArcLength& first, const SegmentArcLength& second,
                                                  std::size_t level)
    {
        const std::vector<std::uint32_t>& order = first.m_counts[level].order;
        const double* const a = first.m_speeds.data();
        const double* const b = second.m_speeds.data();
        const double step = 1.0 / static_cast<double>(order.size() - 1);
        double sum_a = a[order.front()] + a[order.back()];
        double sum_b = b[order.front()] + b[order.back()];
        for (std::size_t i = 1; i + 1 < order.size(); i += 2) {
            sum_a += 4.0 * a[order[i]];
            sum_b += 4.0 * b[order[i]];
            if (i + 2 < order.size()) {
                sum_a += 2.0 * a[order[i + 1]];
                sum_b += 2.0 * b[order[i + 1]];
            }
        }
        return {sum_a * step / 3.0, sum_b * step / 3.0};
    }

    // The length, and the interval count whose sum agreed with the one before it.
    std::pair<double, int> operator()(const HermiteSegment& curve)
    {
        const Converged reached = converge(curve);
        return {reached.summed ? reached.sum : simpson_sum(reached.level), reached.intervals};
    }

private:
    struct Estimate {
        double estimate = 0.0;
        double sum = 0.0; // Simpson's, when `exact`
        bool exact = false;
    };

    static const std::vector<NewParameters>& counts()
    {
        static const std::vector<NewParameters> tabulated = basis_of_each_count();
        return tabulated;
    }

    // Whether the sums of `level` − 1 and `level` agree to 1e-10 (as |finer − sum| ≤ 1e-10·finer
    // decides on Simpson's sums); an undecided estimate makes both sums exact.
    bool agree(Estimate& coarser, Estimate& finer, std::size_t level) const
    {
        const double larger = std::max(coarser.estimate, finer.estimate);
        const double terms = static_cast<double>(m_counts[level].order.size());
        // Each sum within terms·2^-53 of the truth; four times that keeps clear of the rounding
        // of this test itself. Tiny or huge lengths (where a scaling is not exact) are summed.
        const double margin = 16.0 * terms * 0x1p-53 * larger;
        const double difference = std::abs(finer.estimate - coarser.estimate);
        const double allowed = 1e-10 * finer.estimate;
        const bool estimable = std::isfinite(difference) && larger > 1e-200 && larger < 1e200;
        if (estimable && difference - allowed > margin)
            return false;
        if (estimable && allowed - difference > margin)
            return true;
        for (auto [estimate, at] : {std::pair{&coarser, level - 1}, std::pair{&finer, level}})
            if (!estimate->exact)
                *estimate = {estimate->estimate, simpson_sum(at), true};
        return std::abs(finer.sum - coarser.sum) <= 1e-10 * finer.sum;
    }

    // The speeds at the parameters `at` adds, after those kept.
    void add_speeds(const HermiteSegment& curve, const NewParameters& at)
    {
        const std::size_t kept = m_speeds.size();
        m_speeds.resize(kept + at.basis[0].size());
        speeds_at(curve, at, m_speeds.data() + kept);
    }

    const std::vector<NewParameters>& m_counts;
    std::vector<double> m_speeds; // as `order` lists them
};

} // namespace

void CurveArcLengths::measure(std::span<const HermiteSegment> segments)
{
    m_intervals.assign(segments.size(), 0);
    m_segment_length.assign(segments.size(), 0.0);
    m_cumulative.assign(segments.size() + 1, 0.0);
    measure_range(segments, 0, segments.size());
    add_up_from(0);
    m_pending_first = m_pending_end = 0;
    m_sum_from = m_cumulative.size();
}

void CurveArcLengths::remeasure(std::span<const HermiteSegment> segments, const SegmentSplice& change)
{
    mark_changed(segments, change);
    measure_pending(segments, segments.size());
}

void CurveArcLengths::mark_changed(std::span<const HermiteSegment> segments, const SegmentSplice& change)
{
    const bool fits = change.old_end() <= m_segment_length.size() &&
                      m_segment_length.size() - change.removed + change.inserted == segments.size();
    if (!fits)
        return mark_all(segments);
    const auto moved = [&](std::size_t index, bool is_end) { return change.moved(index, is_end); };
    const bool had_pending = m_pending_first < m_pending_end;
    const std::size_t first = had_pending ? std::min(moved(m_pending_first, false), change.first) : change.first;
    const std::size_t end = had_pending ? std::max(moved(m_pending_end, true), change.new_end()) : change.new_end();
    const std::size_t sum_from = std::min(m_sum_from >= m_cumulative.size() ? change.first : moved(m_sum_from, false),
                                          change.first);
    splice_room(m_intervals, change);
    splice_room(m_segment_length, change);
    m_cumulative.resize(segments.size() + 1);
    m_pending_first = first;
    m_pending_end = end;
    m_sum_from = sum_from;
}

void CurveArcLengths::mark_all(std::span<const HermiteSegment> segments)
{
    m_intervals.assign(segments.size(), 0);
    m_segment_length.assign(segments.size(), 0.0);
    m_cumulative.assign(segments.size() + 1, 0.0);
    m_pending_first = 0;
    m_pending_end = segments.size();
    m_sum_from = 0;
}

void CurveArcLengths::measure_pending(std::span<const HermiteSegment> segments, std::size_t most_segments)
{
    const std::size_t end = m_pending_first + std::min(most_segments, m_pending_end - m_pending_first);
    measure_range(segments, m_pending_first, end);
    m_pending_first = end;
    if (m_pending_first < m_pending_end)
        return;
    m_pending_first = m_pending_end = 0;
    if (m_sum_from < m_cumulative.size())
        add_up_from(m_sum_from);
    m_sum_from = m_cumulative.size();
}

// A global change of 10^6 segments measures them on both cores; each segment alike either way.
void CurveArcLengths::measure_range(std::span<const HermiteSegment> segments, std::size_t first, std::size_t end)
{
    split_across_cores(end - first, 1024, [&](std::size_t from, std::size_t to) {
        // Two segments at a time, so that their final sums (one addition after another) run side by
        // side when their counts agree, as neighbours' mostly do.
        std::array<SegmentArcLength, 2> measure;
        std::size_t k = first + from;
        for (; k + 1 < first + to; k += 2) {
            const SegmentArcLength::Converged one = measure[0].converge(segments[k]);
            const SegmentArcLength::Converged two = measure[1].converge(segments[k + 1]);
            m_intervals[k] = one.intervals;
            m_intervals[k + 1] = two.intervals;
            if (!one.summed && !two.summed && one.level == two.level) {
                std::tie(m_segment_length[k], m_segment_length[k + 1]) =
                    SegmentArcLength::simpson_sums(measure[0], measure[1], one.level);
                continue;
            }
            m_segment_length[k] = one.summed ? one.sum : measure[0].simpson_sum(one.level);
            m_segment_length[k + 1] = two.summed ? two.sum : measure[1].simpson_sum(two.level);
        }
        if (k < first + to)
            std::tie(m_segment_length[k], m_intervals[k]) = measure[0](segments[k]);
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
    // Newton's steps (the length's derivative is the speed), kept inside a bracket that halves
    // whenever a step would leave it: a few Simpson sums where halving alone took some forty.
    const HermiteSegment& curve = segments[segment];
    const double segment_length = m_cumulative[segment + 1] - m_cumulative[segment];
    double low = 0.0;
    double high = 1.0;
    double u = segment_length > 0.0 ? std::clamp(within / segment_length, 0.0, 1.0) : 0.5;
    // 200 steps reach the resolution of a double long before; the bound only guarantees an end.
    for (int iteration = 0; iteration < 200 && high - low > 1e-15; ++iteration) {
        const double reached = simpson(curve, u, m_intervals[segment]);
        if (std::abs(reached - within) <= tolerance)
            return {segment, u};
        (reached < within ? low : high) = u;
        const double speed = length(curve.derivative_at(u));
        const double step = speed > 0.0 ? u - (reached - within) / speed : low - 1.0;
        u = step > low && step < high ? step : (low + high) / 2.0;
    }
    return {segment, u};
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

namespace {

constexpr std::size_t halfway_panels = 16;

} // namespace

// Five-point Gauss–Legendre: exact for a speed polynomial of degree 9.
double speed_integral(const HermiteSegment& segment, double from, double to)
{
    constexpr std::array<double, 5> nodes{0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                          0.9061798459386640};
    constexpr std::array<double, 5> weights{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                            0.2369268850561891, 0.2369268850561891};
    const double half = (to - from) / 2.0;
    const double middle = (to + from) / 2.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        sum += weights[i] * length(segment.derivative_at(middle + half * nodes[i]));
    return sum * half;
}

double halfway_parameter(const HermiteSegment& segment)
{
    std::array<double, halfway_panels + 1> cumulative{};
    for (std::size_t p = 0; p < halfway_panels; ++p)
        cumulative[p + 1] = cumulative[p] + speed_integral(segment, static_cast<double>(p) / halfway_panels,
                                                           static_cast<double>(p + 1) / halfway_panels);
    const double total = cumulative.back();
    if (!(total > 0.0))
        return 0.5;
    const double target = total / 2.0;
    const auto panel_end = std::lower_bound(cumulative.begin() + 1, cumulative.end(), target);
    const auto panel = static_cast<std::size_t>(panel_end - cumulative.begin()) - 1;
    const double panel_start = static_cast<double>(panel) / halfway_panels;
    const double within = target - cumulative[panel];
    double low = panel_start;
    double high = static_cast<double>(panel + 1) / halfway_panels;
    // Where the panel's length runs on evenly: a symmetric segment's half lands on u = 0.5 at once.
    const double panel_length = cumulative[panel + 1] - cumulative[panel];
    double u = panel_length > 0.0 ? std::clamp(low + (high - low) * within / panel_length, low, high)
                                  : (low + high) / 2.0;
    // Newton's steps kept inside a bracket that halves when a step would leave it; the bound only
    // guarantees an end (a double's resolution is reached in some 60 halvings).
    for (int iteration = 0; iteration < 100 && high - low > 1e-15; ++iteration) {
        const double reached = speed_integral(segment, panel_start, u);
        if (std::abs(reached - within) <= 1e-15 * total)
            return u;
        (reached < within ? low : high) = u;
        const double speed = length(segment.derivative_at(u));
        const double step = speed > 0.0 ? u - (reached - within) / speed : low - 1.0;
        u = step > low && step < high ? step : (low + high) / 2.0;
    }
    return u;
}

} // namespace apcs
