#include "apcs/animation/kochanek_bartels.h"

#include "apcs/animation/input_limits.h"
#include "apcs/base/parallel_work.h"

#include <cassert>

namespace apcs {

namespace {

// Tension t, continuity c and bias b of Eq. 3.1.4, each clamped to [-1, 1].
struct Shape {
    double t;
    double c;
    double b;
};

Shape clamped_shape(const StaffValues& staff)
{
    return {limits::staff_value.clamp(staff.tension), limits::staff_value.clamp(staff.continuity),
            limits::staff_value.clamp(staff.bias)};
}

} // namespace

Vec3 incoming_tangent(const Vec3& previous, const Vec3& current, const Vec3& next, const StaffValues& staff)
{
    const auto [t, c, b] = clamped_shape(staff);
    return ((1 - t) * (1 - c) * (1 + b) * (current - previous) + (1 - t) * (1 + c) * (1 - b) * (next - current)) * 0.5;
}

Vec3 outgoing_tangent(const Vec3& previous, const Vec3& current, const Vec3& next, const StaffValues& staff)
{
    const auto [t, c, b] = clamped_shape(staff);
    return ((1 - t) * (1 + c) * (1 + b) * (current - previous) + (1 - t) * (1 - c) * (1 - b) * (next - current)) * 0.5;
}

HermiteSegment kb_segment(std::span<const ControlPoint> points, EndSlopes slopes, std::size_t k)
{
    assert(k + 1 < points.size());
    const std::size_t last = points.size() - 1;
    const Vec3& start = points[k].position;
    const Vec3& end = points[k + 1].position;
    const Vec3 start_tangent = k == 0 ? limits::end_slope.clamp(slopes.start) * (end - start)
                                      : outgoing_tangent(points[k - 1].position, start, end, points[k].staff);
    const Vec3 end_tangent = k + 1 == last ? limits::end_slope.clamp(slopes.end) * (end - start)
                                           : incoming_tangent(start, end, points[k + 2].position, points[k + 1].staff);
    return {start, end, start_tangent, end_tangent};
}

namespace {

// Segment k into out[k], for every k; a long path's on both cores.
void make_segments(std::span<const ControlPoint> points, EndSlopes slopes, std::span<HermiteSegment> out)
{
    split_across_cores(out.size(), std::size_t{1} << 14, [&](std::size_t first, std::size_t end) {
        for (std::size_t k = first; k < end; ++k)
            out[k] = kb_segment(points, slopes, k);
    });
}

std::size_t segment_count(std::span<const ControlPoint> points) { return points.size() < 2 ? 0 : points.size() - 1; }

} // namespace

std::vector<HermiteSegment> kb_segments(std::span<const ControlPoint> points, EndSlopes slopes)
{
    std::vector<HermiteSegment> segments(segment_count(points));
    make_segments(points, slopes, segments);
    return segments;
}

void kb_segments(std::span<const ControlPoint> points, EndSlopes slopes, HermiteSegments& segments)
{
    segments.resize(segment_count(points));
    make_segments(points, slopes, segments);
}

PointTangents tangents_at(std::span<const HermiteSegment> segments, std::size_t point)
{
    PointTangents tangents;
    if (point >= 1 && point <= segments.size())
        tangents.incoming = segments[point - 1].end_tangent;
    if (point < segments.size())
        tangents.outgoing = segments[point].start_tangent;
    return tangents;
}

} // namespace apcs
