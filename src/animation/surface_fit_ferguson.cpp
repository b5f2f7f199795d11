// The thesis' own surface fitting (Ch. 3.2, fig. 3.2.1; SPEC §5.3.1): a Ferguson surface, bicubic
// with zero twist, from the four corners' positions and u-tangents.
#include "apcs/animation/arc_length.h"
#include "apcs/animation/surface_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace apcs {

EdgeTangents edge_tangents_of(const EvaluatedPath& path)
{
    const HermiteSegments& segments = path.curve.segments;
    if (segments.empty())
        return {};
    return {segments.front().start_tangent, segments.back().end_tangent};
}

namespace {

// The u-tangent of a zero-twist Ferguson surface along one key at v (thesis Ch. 3.2): the twist
// terms vanish, so it is the cubic blend F1(v)·T_first + F2(v)·T_last of the corners' tangents.
Vec3 u_tangent_at(double v, const Vec3& first_tangent, const Vec3& last_tangent)
{
    const HermiteBasis weights = hermite_basis(v);
    return weights.f1 * first_tangent + weights.f2 * last_tangent;
}

} // namespace

std::vector<HermiteSegment> ferguson_point_paths(std::span<const Vec3> key1, std::span<const Vec3> key2,
                                                 Closure closure, const FergusonCorners& corners)
{
    const std::size_t count = std::min(key1.size(), key2.size());
    // A closed graphic's last point is its first (SPEC §5.3): both corners' tangents are the first path's.
    const EdgeTangents& last = closure == Closure::closed ? corners.first : corners.last;
    const std::vector<double> along_key1 = chord_places(key1.first(count), closure);
    const std::vector<double> along_key2 = chord_places(key2.first(count), closure);
    std::vector<HermiteSegment> paths(count);
    for (std::size_t i = 0; i < count; ++i) {
        paths[i] = {key1[i], key2[i], u_tangent_at(along_key1[i], corners.first.start, last.start),
                    u_tangent_at(along_key2[i], corners.first.end, last.end)};
    }
    return paths;
}

namespace {

// The same on [a, b] as two halves, each by the five-point rule: the rule the table keeps.
double piece_integral(const HermiteSegment& segment, double a, double b)
{
    const double middle = (a + b) / 2.0;
    return speed_integral(segment, a, middle) + speed_integral(segment, middle, b);
}

} // namespace

MeasuredSegment::MeasuredSegment(const HermiteSegment& segment)
    : m_segment(segment)
{
    constexpr double step = 1.0 / knots;
    // Each piece by the rule on its halves, kept; and by the rule once, against it. Halving the
    // pieces shrinks the rule's error about a thousandfold (h^10), so a difference of 1e-8 of the
    // length leaves the halves within about 1e-11 of it.
    // Each piece's difference counts on its own: errors of opposite signs must not cancel.
    double differences = 0.0;
    for (int j = 0; j < knots; ++j) {
        const double a = j * step;
        const auto k = static_cast<std::size_t>(j);
        const double piece = piece_integral(m_segment, a, a + step);
        m_at_knot[k + 1] = m_at_knot[k] + piece;
        differences += std::abs(speed_integral(m_segment, a, a + step) - piece);
    }
    const double total = m_at_knot.back();
    if (differences > 1e-8 * total) {
        auto adaptive = std::make_shared<CurveArcLengths>();
        adaptive->measure(std::span(&m_segment, 1));
        m_adaptive = std::move(adaptive);
    }
}

double MeasuredSegment::length_at(double u) const
{
    if (m_adaptive)
        return m_adaptive->length_at(std::span(&m_segment, 1), {0, u});
    const int knot = std::clamp(static_cast<int>(u * knots), 0, knots - 1);
    const double from = static_cast<double>(knot) / knots;
    return m_at_knot[static_cast<std::size_t>(knot)] + piece_integral(m_segment, from, u);
}

// Newton's steps on s(u) − target, s' = |P'(u)|, from the place between the knots that bracket
// the target (linear between their lengths), kept inside the bracket that bisection would keep: a
// couple of steps where bisection takes about forty.
Vec3 MeasuredSegment::at_arc_fraction(double fraction) const
{
    const double total = m_adaptive ? m_adaptive->total_length() : m_at_knot.back();
    if (!(total > 0.0))
        return m_segment.start;
    const double target = std::clamp(fraction, 0.0, 1.0) * total;
    const double tolerance = 1e-12 * total;
    double low = 0.0;
    double high = 1.0;
    double u = std::clamp(fraction, 0.0, 1.0);
    if (!m_adaptive) {
        const auto above = std::upper_bound(m_at_knot.begin() + 1, m_at_knot.end() - 1, target);
        const auto knot = static_cast<std::size_t>(above - m_at_knot.begin()) - 1;
        low = static_cast<double>(knot) / knots;
        high = static_cast<double>(knot + 1) / knots;
        const double piece = m_at_knot[knot + 1] - m_at_knot[knot];
        u = piece > 0.0 ? low + (target - m_at_knot[knot]) / piece * (high - low) : low;
    }
    for (int step = 0; step < 100 && high - low > 1e-15; ++step) {
        const double error = length_at(u) - target;
        if (std::abs(error) <= tolerance)
            break;
        (error < 0.0 ? low : high) = u;
        const double speed = length(m_segment.derivative_at(u));
        const double newton = speed > 0.0 ? u - error / speed : low;
        u = newton > low && newton < high ? newton : (low + high) / 2.0;
        // Newton's error squares at each step: from within 1e-7 of the length, this step lands
        // within about 1e-14 of it, and measuring again would only confirm it (on the table's
        // pieces, where the speed changes by little).
        if (!m_adaptive && u == newton && std::abs(error) < 1e-7 * total)
            break;
    }
    return m_segment.point_at(u);
}

Vec3 point_at_arc_fraction(const HermiteSegment& segment, double fraction)
{
    return MeasuredSegment(segment).at_arc_fraction(fraction);
}

} // namespace apcs
