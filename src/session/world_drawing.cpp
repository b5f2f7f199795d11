#include "apcs/session/world_drawing.h"

#include "apcs/session/curve_raster.h"

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

ViewTransform ViewScene::fit(ViewAngles angles, PixelRect drawing_area) const
{
    return ViewTransform::fit_visiting(angles, [this](const auto& visit) { for_each_point(visit); }, drawing_area);
}

BoundingBox ViewScene::bounds() const
{
    BoundingBox box;
    for_each_point([&](const Vec3& point) { box.add(point); });
    return box;
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
