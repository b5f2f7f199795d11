#include "apcs/animation/kochanek_bartels.h"

namespace apcs {

Vec3 incoming_tangent(const Vec3& previous, const Vec3& current, const Vec3& next, const StaffValues& staff)
{
    const double t = staff.tension;
    const double c = staff.continuity;
    const double b = staff.bias;
    return ((1 - t) * (1 - c) * (1 + b) * (current - previous) + (1 - t) * (1 + c) * (1 - b) * (next - current)) * 0.5;
}

Vec3 outgoing_tangent(const Vec3& previous, const Vec3& current, const Vec3& next, const StaffValues& staff)
{
    const double t = staff.tension;
    const double c = staff.continuity;
    const double b = staff.bias;
    return ((1 - t) * (1 + c) * (1 + b) * (current - previous) + (1 - t) * (1 - c) * (1 - b) * (next - current)) * 0.5;
}

std::vector<HermiteSegment> kb_segments(std::span<const ControlPoint> points, EndSlopes slopes)
{
    std::vector<HermiteSegment> segments;
    if (points.size() < 2)
        return segments;
    const std::size_t last = points.size() - 1;
    segments.reserve(last);
    for (std::size_t k = 0; k < last; ++k) {
        const Vec3& start = points[k].position;
        const Vec3& end = points[k + 1].position;
        const Vec3 start_tangent = k == 0
            ? slopes.start * (end - start)
            : outgoing_tangent(points[k - 1].position, start, end, points[k].staff);
        const Vec3 end_tangent = k + 1 == last
            ? slopes.end * (end - start)
            : incoming_tangent(start, end, points[k + 2].position, points[k + 1].staff);
        segments.push_back({start, end, start_tangent, end_tangent});
    }
    return segments;
}

} // namespace apcs
