#include "apcs/session/world_drawing.h"

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
    return ViewTransform::fit(angles, m_points, drawing_area);
}

void draw_world_polyline(Painter& painter, std::span<const Vec3> polyline, const ViewTransform& view, LineStyle style)
{
    if (polyline.size() == 1)
        painter.pixel(view.to_device(polyline.front()).rounded());
    int phase = 0;
    for (std::size_t i = 1; i < polyline.size(); ++i)
        painter.styled_line(view.to_device(polyline[i - 1]).rounded(), view.to_device(polyline[i]).rounded(), style,
                            phase);
}

} // namespace apcs
