#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/hermite.h"

#include <optional>
#include <span>
#include <vector>

namespace apcs {

// DS_k, the incoming ("source") tangent at an interior control point (thesis Eq. 3.1.4):
// [(1−t)(1−c)(1+b)(P_k−P_{k−1}) + (1−t)(1+c)(1−b)(P_{k+1}−P_k)] / 2.
// The staff's tension t, continuity c and bias b are clamped to [-1, 1] (limits::staff_value);
// its acceleration plays no part here.
Vec3 incoming_tangent(const Vec3& previous, const Vec3& current, const Vec3& next, const StaffValues& staff);

// DD_k, the outgoing ("destination") tangent (Eq. 3.1.4), t, c and b clamped to [-1, 1]:
// [(1−t)(1+c)(1+b)(P_k−P_{k−1}) + (1−t)(1−c)(1−b)(P_{k+1}−P_k)] / 2.
Vec3 outgoing_tangent(const Vec3& previous, const Vec3& current, const Vec3& next, const StaffValues& staff);

// The Hermite segments k → k+1 of a KB spline (T0 = DD_k, T1 = DS_{k+1}). The first point's
// outgoing tangent is slopes.start·(P_1−P_0), the last point's incoming one slopes.end·(P_n−P_{n−1}),
// each slope clamped to [0, 1] (limits::end_slope); interior tangents clamp t, c, b as above.
// Fewer than two control points give no segments.
std::vector<HermiteSegment> kb_segments(std::span<const ControlPoint> points, EndSlopes slopes);
// The same into `segments`, whose room is kept (a long path's segments are made again at every
// staff key of a global change), a long path's on both cores.
void kb_segments(std::span<const ControlPoint> points, EndSlopes slopes, HermiteSegments& segments);
// Segment k alone (k + 1 < points.size()): it depends on control points k − 1 … k + 2.
HermiteSegment kb_segment(std::span<const ControlPoint> points, EndSlopes slopes, std::size_t k);

// The tangents at control point `point` of a path made of `segments` (kb_segments): DS, the
// incoming one, is segment point−1's end tangent; DD, the outgoing one, segment point's start
// tangent. The first control point has no DS, the last no DD; a point past the end has neither.
struct PointTangents {
    std::optional<Vec3> incoming; // DS_k
    std::optional<Vec3> outgoing; // DD_k
};
PointTangents tangents_at(std::span<const HermiteSegment> segments, std::size_t point);

} // namespace apcs
