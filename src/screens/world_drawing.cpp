#include "apcs/screens/world_drawing.h"

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
    for (const ControlPoint& point : points)
        m_points.push_back(point.position);
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

} // namespace

ViewTransform ViewScene::fill(ViewAngles angles, PixelRect area) const
{
    ViewTransform view = ViewTransform::centred_on(angles, bounds(), area);
    ProjectedExtent extent;
    const auto reach = [&](const Vec3& point) { extent.add(view.to_eye(point)); };
    for_each_control_point(reach);
    const ProjectedExtent known = extent;
    for_each_sample_beyond([&](const HermiteSegment& segment) { return hull_inside_extent(segment, view, known); },
                           reach);
    view.fill(extent, area);
    return view;
}

// fit_visiting's two passes, each over the points and the curves' control points first, then the
// samples of the segments that could reach further: the same extremes (maxima do not depend on
// the order of the points), so the same view to the bit.
ViewTransform ViewScene::fit(ViewAngles angles, PixelRect drawing_area) const
{
    ViewTransform view = ViewTransform::centred_on(angles, bounds(), drawing_area);
    double widest = 0.0;
    double tallest = 0.0;
    const auto reach = [&](const Vec3& point) {
        const EyePoint eye = view.to_eye(point);
        widest = std::max(widest, std::abs(eye.x / eye.z));
        tallest = std::max(tallest, std::abs(eye.y / eye.z));
    };
    for_each_control_point(reach);
    const double known_widest = widest;
    const double known_tallest = tallest;
    for_each_sample_beyond(
        [&](const HermiteSegment& segment) { return hull_inside_focus(segment, view, known_widest, known_tallest); },
        reach);
    view.focus_on(widest, tallest, drawing_area);
    return view;
}

BoundingBox ViewScene::bounds() const
{
    BoundingBox known;
    for_each_control_point([&](const Vec3& point) { known.add(point); });
    BoundingBox box = known;
    for_each_sample_beyond([&](const HermiteSegment& segment) { return hull_inside_box(segment, known); },
                           [&](const Vec3& point) { box.add(point); });
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
