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
        scene.add(content.path->curve);
    return scene.add(content.key_frame_polylines);
}

std::vector<ControlPointRun> control_point_runs(std::span<const ControlPoint> points, const ViewTransform& view)
{
    std::vector<ControlPointRun> runs;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const PixelPoint at = view.to_device(points[k].position).rounded();
        if (!runs.empty() && runs.back().at == at)
            runs.back().last = k;
        else
            runs.push_back({at, k, k});
    }
    return runs;
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
// Points that share a pixel one after another show one mark (the same mark drawn again changes
// nothing), split where the region starts or ends.
void pre_draw(GraphicsScreen& screen, const PathScreenContent& content, const ViewTransform& view)
{
    std::vector<ControlPointRun> found;
    std::span<const ControlPointRun> runs = content.control_point_runs;
    if (runs.empty() && !content.control_points.empty()) {
        found = control_point_runs(content.control_points, view);
        runs = found;
    }
    for (const ControlPointRun& run : runs) {
        if (!content.region || run.last < content.region->first || run.first > content.region->second) {
            screen.marks.push_back({run.at, MarkKind::control_point});
            continue;
        }
        if (run.first < content.region->first)
            screen.marks.push_back({run.at, MarkKind::control_point});
        screen.marks.push_back({run.at, MarkKind::control_point, CellStyle::reverse});
        if (run.last > content.region->second)
            screen.marks.push_back({run.at, MarkKind::control_point});
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
        if (content.curve_raster != nullptr)
            content.curve_raster->draw(screen.bitmap);
        else
            draw_world_curve(inside, content.path->curve, view);
        draw_ani_path(screen, *content.path, view);
        if (content.tangent_scale) {
            draw_tangent_arrows(screen, inside, content.path->curve.segments, view, *content.tangent_scale);
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
