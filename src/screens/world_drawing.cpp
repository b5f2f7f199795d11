#include "apcs/screens/world_drawing.h"

#include "apcs/base/parallel_work.h"
#include "apcs/screens/curve_raster.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace apcs {

ViewScene& ViewScene::add(std::span<const Vec3> points)
{
    m_points.insert(m_points.end(), points.begin(), points.end());
    return *this;
}

ViewScene& ViewScene::add(std::span<const ControlPoint> points)
{
    m_control_points.push_back(points);
    return *this;
}

ViewScene& ViewScene::add(const SampledCurve& curve)
{
    m_curves.push_back(&curve);
    return *this;
}

ViewScene& ViewScene::add(const FrameSequence& frames)
{
    for (std::size_t k = 0; k < frames.frame_count(); ++k)
        add(frames.frame(k));
    return *this;
}

ViewScene& ViewScene::add(const std::vector<std::vector<Vec3>>& polylines)
{
    for (const std::vector<Vec3>& polyline : polylines)
        add(std::span<const Vec3>(polyline));
    return *this;
}

namespace {

// A segment's samples lie in the hull of its Bézier points P0, P0 + T0/3, P1 − T1/3, P1 (their
// computed values within about 1e-15 of the coordinates' and tangents' sizes of it). A segment
// whose hull lies inside what the scene's points already reach, by a margin a million times that,
// can hold no sample that reaches further: its samples need not be visited. A long path's segments
// are mostly such (ViewTransform::fit_visiting visits 3.2·10^7 samples of 10^6 control points).
constexpr double hull_margin = 1e-6;

std::array<Vec3, 4> bezier_hull(const HermiteSegment& segment)
{
    return {segment.start, segment.start + segment.start_tangent * (1.0 / 3.0),
            segment.end - segment.end_tangent * (1.0 / 3.0), segment.end};
}

// The sizes a coordinate's rounding errors scale with, one per axis.
Vec3 error_scale(const HermiteSegment& segment)
{
    const auto size = [](double start, double end, double start_tangent, double end_tangent) {
        return std::abs(start) + std::abs(end) + std::abs(start_tangent) + std::abs(end_tangent);
    };
    const auto& [start, end, start_tangent, end_tangent] = segment;
    return {size(start.x, end.x, start_tangent.x, end_tangent.x), size(start.y, end.y, start_tangent.y, end_tangent.y),
            size(start.z, end.z, start_tangent.z, end_tangent.z)};
}

bool hull_inside_box(const HermiteSegment& segment, const BoundingBox& box)
{
    const Vec3 margin = error_scale(segment) * hull_margin;
    for (const Vec3& point : bezier_hull(segment)) {
        const Vec3 low = point - box.low();
        const Vec3 high = box.high() - point;
        if (low.x <= margin.x || low.y <= margin.y || low.z <= margin.z || high.x <= margin.x ||
            high.y <= margin.y || high.z <= margin.z)
            return false;
    }
    return true;
}

// In front of the eye, x_e/z_e and y_e/z_e over a convex set are largest at a vertex.
bool hull_inside_focus(const HermiteSegment& segment, const ViewTransform& view, double widest, double tallest)
{
    for (const Vec3& point : bezier_hull(segment)) {
        const EyePoint eye = view.to_eye(point);
        if (!(eye.z > 0.0) || !(std::abs(eye.x / eye.z) < widest * (1.0 - hull_margin)) ||
            !(std::abs(eye.y / eye.z) < tallest * (1.0 - hull_margin)))
            return false;
    }
    return true;
}

// The extent's own hull test: every Bézier point strictly inside it, by hull_margin of its size.
bool hull_inside_extent(const HermiteSegment& segment, const ViewTransform& view, const ProjectedExtent& extent)
{
    for (const Vec3& point : bezier_hull(segment))
        if (!extent.holds(view.to_eye(point), hull_margin))
            return false;
    return true;
}

// Below this many points a list is gone over on one core.
constexpr std::size_t points_worth_a_thread = std::size_t{1} << 14;

// reach(extent, index) for the indices 0 … count − 1, in two halves on both cores when there are
// many; each half's extent is kept on its own thread's stack (no cache line written by both) and
// joined to `extent` in the halves' order.
template <typename Extent, typename ReachIndex>
void reach_in_halves(Extent& extent, std::size_t count, const ReachIndex& reach)
{
    std::array<Extent, 2> halves;
    split_across_cores(count, points_worth_a_thread, [&](std::size_t first, std::size_t end) {
        Extent half;
        for (std::size_t index = first; index < end; ++index)
            reach(half, index);
        halves[first == 0 ? 0 : 1] = half;
    });
    extent.join(halves[0]);
    extent.join(halves[1]);
}

// How far a fit's projection reaches from the middle: the largest |x_e/z_e| and |y_e/z_e|.
struct ProjectedFocus {
    double widest = 0.0;
    double tallest = 0.0;

    void join(const ProjectedFocus& other)
    {
        widest = std::max(widest, other.widest);
        tallest = std::max(tallest, other.tallest);
    }
};

} // namespace

template <typename Extent, typename Reach>
void ViewScene::reach_control_points(Extent& extent, const Reach& reach) const
{
    for (const std::span<const ControlPoint> points : m_control_points)
        reach_in_halves(extent, points.size(), [&](Extent& half, std::size_t k) { reach(half, points[k].position); });
    reach_in_halves(extent, m_points.size(), [&](Extent& half, std::size_t k) { reach(half, m_points[k]); });
    for (const SampledCurve* curve : m_curves) {
        const HermiteSegments& segments = curve->segments;
        reach_in_halves(extent, segments.size(), [&](Extent& half, std::size_t s) { reach(half, segments[s].start); });
        if (!segments.empty())
            reach(extent, segments.back().end);
    }
}

template <typename Extent, typename Within, typename Reach>
void ViewScene::reach_samples_beyond(Extent& extent, const Within& within, const Reach& reach) const
{
    for (const SampledCurve* curve : m_curves) {
        const auto per_segment = static_cast<std::size_t>(curve->samples_per_segment);
        reach_in_halves(extent, curve->segments.size(), [&](Extent& half, std::size_t s) {
            if (!within(curve->segments[s]))
                for (std::size_t j = 0; j <= per_segment; ++j)
                    reach(half, curve->segment_sample(s, j));
        });
    }
}

ViewTransform ViewScene::fill(ViewAngles angles, PixelRect area) const
{
    ViewTransform view = ViewTransform::centred_on(angles, bounds(), area);
    const auto reach = [&view](ProjectedExtent& extent, const Vec3& point) { extent.add(view.to_eye(point)); };
    ProjectedExtent extent;
    reach_control_points(extent, reach);
    const ProjectedExtent known = extent;
    reach_samples_beyond(
        extent, [&](const HermiteSegment& segment) { return hull_inside_extent(segment, view, known); }, reach);
    view.fill(extent, area);
    return view;
}

// fit_visiting's two passes, each over the points and the curves' control points first, then the
// samples of the segments that could reach further: the same extremes (maxima do not depend on
// the order of the points), so the same view to the bit.
ViewTransform ViewScene::fit(ViewAngles angles, PixelRect drawing_area) const
{
    ViewTransform view = ViewTransform::centred_on(angles, bounds(), drawing_area);
    const auto reach = [&view](ProjectedFocus& focus, const Vec3& point) {
        const EyePoint eye = view.to_eye(point);
        focus.widest = std::max(focus.widest, std::abs(eye.x / eye.z));
        focus.tallest = std::max(focus.tallest, std::abs(eye.y / eye.z));
    };
    ProjectedFocus focus;
    reach_control_points(focus, reach);
    const ProjectedFocus known = focus;
    reach_samples_beyond(
        focus,
        [&](const HermiteSegment& segment) { return hull_inside_focus(segment, view, known.widest, known.tallest); },
        reach);
    view.focus_on(focus.widest, focus.tallest, drawing_area);
    return view;
}

BoundingBox ViewScene::bounds() const
{
    const auto reach = [](BoundingBox& box, const Vec3& point) { box.add(point); };
    BoundingBox known;
    reach_control_points(known, reach);
    BoundingBox box = known;
    reach_samples_beyond(box, [&](const HermiteSegment& segment) { return hull_inside_box(segment, known); }, reach);
    return box;
}

void draw_world_graphic(Painter& painter, const Graphic& structure, std::span<const Vec3> points,
                        const ViewTransform& view, LineStyle style)
{
    for (const std::vector<Vec3>& polyline : structure.polylines(points))
        draw_world_polyline(painter, polyline, view, style);
}

void draw_world_polyline(Painter& painter, std::span<const Vec3> polyline, const ViewTransform& view, LineStyle style)
{
    if (polyline.empty())
        return;
    PixelPoint from = view.to_device(polyline.front()).rounded();
    if (polyline.size() == 1)
        painter.pixel(from);
    int phase = 0;
    for (std::size_t i = 1; i < polyline.size(); ++i) {
        const PixelPoint to = view.to_device(polyline[i]).rounded();
        // A long path has many samples on one pixel: a segment that stays on the pixel where the
        // last one ended draws nothing and moves no dash (after the first), so it is skipped.
        if (to == from && phase > 0)
            continue;
        painter.styled_line(from, to, style, phase);
        from = to;
    }
}

void draw_world_curve(Painter& painter, const SampledCurve& curve, const ViewTransform& view, LineStyle style)
{
    int phase = 0;
    for_each_curve_line(curve, view, 0, curve.segments.size(),
                        [&](const PixelLine& line) { painter.styled_line(line.from, line.to, style, phase); });
}

} // namespace apcs
