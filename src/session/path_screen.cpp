#include "apcs/session/path_screen.h"

#include "apcs/raster/painter.h"
#include "apcs/geometry/hercules.h"
#include "apcs/session/path_overlays.h"
#include "apcs/session/screen_layout.h"
#include "apcs/session/world_drawing.h"

#include <cmath>

namespace apcs {

PathScreenContent path_screen_content(std::span<const ControlPoint> points, const EvaluatedPath& path)
{
    PathScreenContent content;
    content.path = &path;
    content.control_points = points;
    content.staff = points.empty() ? StaffValues{} : points.front().staff;
    return content;
}

ViewScene path_screen_scene(const PathScreenContent& content)
{
    ViewScene scene;
    scene.add(content.control_points);
    if (content.path != nullptr)
        scene.add(content.path->curve.points);
    return scene.add(content.key_frame_polylines);
}

namespace {

void draw_staff(Painter& painter, GraphicsScreen& screen, const PathScreenContent& content)
{
    for (const StaffLine line : staff_lines) {
        const int index = static_cast<int>(line);
        const int y = layout::staff_line_y(index);
        const int row = layout::first_staff_row + index;
        const bool active = content.active_line == line;
        screen.text.push_back({0, row, std::string(active ? ">" : " ") + std::string(staff_line_name(line)),
                               active ? CellStyle::reverse : CellStyle::plain});
        painter.line({layout::staff_left, y}, {layout::staff_right, y});
        for (const double tick : {-1.0, 0.0, 1.0})
            painter.line({layout::staff_x(tick), y - layout::staff_tick_half_height},
                         {layout::staff_x(tick), y + layout::staff_tick_half_height});
        screen.marks.push_back({{layout::staff_x(content.staff[line]), y}, MarkKind::staff_value});
        screen.text.push_back({layout::staff_value_column, row, format_staff_value(content.staff[line])});
    }
}

void draw_dotted(Painter& painter, const std::vector<Vec3>& polyline, const ViewTransform& view)
{
    for (std::size_t i = 0; i < polyline.size(); ++i)
        painter.pixel(view.to_device(polyline[i]).rounded());
    for (std::size_t i = 1; i < polyline.size(); ++i) {
        const DevicePoint a = view.to_device(polyline[i - 1]);
        const DevicePoint b = view.to_device(polyline[i]);
        const int steps = static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / 4.0);
        for (int s = 1; s < steps; ++s) {
            const double f = static_cast<double>(s) / steps;
            painter.pixel(DevicePoint{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)}.rounded());
        }
    }
}

// Draw_Ani_Path: a mark at every in-between the path will show.
void draw_ani_path(GraphicsScreen& screen, const EvaluatedPath& path, const ViewTransform& view)
{
    for (const Inbetween& inbetween : path.inbetweens)
        screen.marks.push_back({view.to_device(inbetween.position).rounded(), MarkKind::inbetween});
}

// Pre_Draw: every control point marked with an x; those of the picked region in reverse video.
void pre_draw(GraphicsScreen& screen, const PathScreenContent& content, const ViewTransform& view)
{
    for (std::size_t k = 0; k < content.control_points.size(); ++k) {
        const bool picked = content.region && k >= content.region->first && k <= content.region->second;
        screen.marks.push_back({view.to_device(content.control_points[k].position).rounded(), MarkKind::control_point,
                                picked ? CellStyle::reverse : CellStyle::plain});
    }
}

// The arrow of Scan_Control_Point: beside its control point, or at the top-left before it moves.
void draw_arrow(GraphicsScreen& screen, const PathScreenContent& content, const ViewTransform& view)
{
    if (content.arrow_at && *content.arrow_at < content.control_points.size())
        screen.marks.push_back(
            {view.to_device(content.control_points[*content.arrow_at].position).rounded(), MarkKind::arrow});
    else if (content.arrow_home)
        screen.marks.push_back({{2 * hercules::cell_width, hercules::text_row_top(1)}, MarkKind::arrow});
}

} // namespace

GraphicsScreen draw_path_screen(const PathScreenContent& content, const ViewTransform& view)
{
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    // Make_Boundary.
    painter.record_into(screen.strokes).rectangle(layout::drawing_area);
    Painter inside(screen.bitmap, layout::inside_boundary);
    inside.record_into(screen.strokes);
    for (const auto& polyline : content.key_frame_polylines)
        draw_dotted(inside, polyline, view);
    if (content.path != nullptr) {
        // DRAW: the KB curve, sampled.
        draw_world_curve(inside, content.path->segments, content.path->curve, view);
        draw_ani_path(screen, *content.path, view);
        if (content.tangent_scale) {
            draw_tangent_arrows(screen, inside, content.path->segments, view, *content.tangent_scale);
            // An arrow's line is clipped at the boundary; its end mark must not sit on it or beside it.
            std::erase_if(screen.marks, [](const PixelMark& mark) {
                return mark.kind == MarkKind::tangent_end && !layout::view_area.contains(mark.at);
            });
        }
    }
    pre_draw(screen, content, view);
    draw_arrow(screen, content, view);
    draw_staff(painter, screen, content);
    if (!content.message.empty())
        screen.text.push_back({1, layout::message_row, content.message});
    if (!content.key_help.empty())
        screen.text.push_back({1, layout::key_help_row, content.key_help});
    if (content.path != nullptr && content.law_span)
        draw_law_inset(screen, *content.path, *content.law_span);
    return screen;
}

} // namespace apcs
