// The thesis' own surface fitting (Ch. 3.2, fig. 3.2.1; SPEC §5.3.1): a Ferguson surface, bicubic
// with zero twist, from the four corners' positions and u-tangents.
#include "apcs/animation/arc_length.h"
#include "apcs/animation/surface_fit.h"

#include <algorithm>

namespace apcs {

EdgeTangents edge_tangents_of(const EvaluatedPath& path)
{
    const std::vector<HermiteSegment>& segments = path.curve.segments;
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

MeasuredSegment::MeasuredSegment(const HermiteSegment& segment)
    : m_segment(segment)
{
    m_lengths.measure(std::span(&m_segment, 1));
}

// Newton's steps on s(u) − target, s' = |P'(u)|, from u = fraction (the place on an evenly
// moving path), kept inside the bracket that bisection would keep: a handful of measurings where
// bisection takes about forty.
Vec3 MeasuredSegment::at_arc_fraction(double fraction) const
{
    const std::span<const HermiteSegment> segments(&m_segment, 1);
    const double total = m_lengths.total_length();
    if (!(total > 0.0))
        return m_segment.start;
    const double target = std::clamp(fraction, 0.0, 1.0) * total;
    const double tolerance = 1e-12 * total;
    double low = 0.0;
    double high = 1.0;
    double u = std::clamp(fraction, 0.0, 1.0);
    for (int step = 0; step < 100 && high - low > 1e-15; ++step) {
        const double error = m_lengths.length_at(segments, {0, u}) - target;
        if (std::abs(error) <= tolerance)
            break;
        (error < 0.0 ? low : high) = u;
        const double speed = length(m_segment.derivative_at(u));
        const double newton = speed > 0.0 ? u - error / speed : low;
        u = newton > low && newton < high ? newton : (low + high) / 2.0;
    }
    return m_segment.point_at(u);
}

Vec3 point_at_arc_fraction(const HermiteSegment& segment, double fraction)
{
    return MeasuredSegment(segment).at_arc_fraction(fraction);
}

} // namespace apcs
