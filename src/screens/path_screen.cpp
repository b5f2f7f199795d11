#include "apcs/screens/path_screen.h"

#include "apcs/raster/painter.h"
#include "apcs/geometry/hercules.h"
#include "apcs/screens/path_overlays.h"
#include "apcs/screens/reference_curve.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/world_drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

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

void update_control_point_runs(std::vector<ControlPointRun>& runs, std::span<const ControlPoint> points,
                               const ViewTransform& view, const PathChange& change)
{
    if (change.what != PathChange::What::positions)
        return;
    const std::size_t old_count = points.size() - change.inserted + change.removed;
    if (runs.empty() || runs.back().last + 1 != old_count || points.empty())
        return void(runs = control_point_runs(points, view));
    // The points changed and their two neighbours are projected again: old points from … old_last
    // are new points from … new_last. The runs holding them keep their other points (a run of
    // thousands on one pixel is not projected again), split off before and after.
    const std::size_t from = change.first > 0 ? change.first - 1 : 0;
    const std::size_t old_last = std::min(change.first + change.removed, old_count - 1);
    const std::size_t new_last = std::min(change.first + change.inserted, points.size() - 1);
    const auto holding = [&](std::size_t point) {
        return std::partition_point(runs.begin(), runs.end(), [&](const ControlPointRun& run) { return run.last < point; });
    };
    const auto first_run = holding(from);
    const auto last_run = holding(old_last);
    std::vector<ControlPointRun> remade;
    if (first_run->first < from)
        remade.push_back({first_run->at, first_run->first, from - 1});
    for (ControlPointRun run : control_point_runs(points.subspan(from, new_last - from + 1), view)) {
        run.first += from;
        run.last += from;
        if (!remade.empty() && remade.back().at == run.at)
            remade.back().last = run.last;
        else
            remade.push_back(run);
    }
    if (last_run->last > old_last) {
        const std::size_t suffix_last = last_run->last - old_count + points.size();
        if (remade.back().at == last_run->at)
            remade.back().last = suffix_last;
        else
            remade.push_back({last_run->at, new_last + 1, suffix_last});
    }
    const auto after = runs.erase(first_run, last_run + 1);
    for (auto run = after; run != runs.end(); ++run) {
        run->first = run->first + points.size() - old_count;
        run->last = run->last + points.size() - old_count;
    }
    runs.insert(after, remade.begin(), remade.end());
}

namespace {

// Calls mark(m) for each run's mark in order, split where the picked region starts or ends.
template <typename Mark>
void for_each_run_mark(std::span<const ControlPointRun> runs, std::optional<ControlRegion> region, Mark mark)
{
    for (const ControlPointRun& run : runs) {
        if (!region || run.last < region->first || run.first > region->last) {
            mark(PixelMark{run.at, MarkKind::control_point});
            continue;
        }
        if (run.first < region->first)
            mark(PixelMark{run.at, MarkKind::control_point});
        mark(PixelMark{run.at, MarkKind::control_point, CellStyle::reverse, ColourRole::region});
        if (run.last > region->last)
            mark(PixelMark{run.at, MarkKind::control_point});
    }
}

} // namespace

// A cell shows the last control point mark laid in it, and a picture draws every mark's x and box:
// so of a pixel's marks the last is kept where it stands, after a boxed copy when an earlier one
// was boxed and the last is not. Marks off the raster are kept as they are (part of an x may show).
std::vector<PixelMark> control_point_marks(std::span<const ControlPointRun> runs, std::optional<ControlRegion> region)
{
    std::vector<PixelMark> all;
    // A few thousand marks cost less laid twice than a table of every pixel.
    constexpr std::size_t worth_a_table = 4096;
    if (runs.size() <= worth_a_table) {
        for_each_run_mark(runs, region, [&](const PixelMark& mark) { all.push_back(mark); });
        if (all.size() <= worth_a_table)
            return all;
    }
    // A scribble's 10^6 runs: the marks are gone over twice rather than held (16 MB written and read).
    const Bitmap raster;
    const auto pixel = [&](const PixelMark& mark) {
        return static_cast<std::size_t>(mark.at.y) * static_cast<std::size_t>(raster.width()) +
               static_cast<std::size_t>(mark.at.x);
    };
    constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> last(static_cast<std::size_t>(raster.width() * raster.height()), none);
    std::vector<std::uint8_t> boxed(last.size(), 0);
    std::uint32_t index = 0;
    for_each_run_mark(runs, region, [&](const PixelMark& mark) {
        if (raster.contains(mark.at.x, mark.at.y)) {
            last[pixel(mark)] = index;
            if (mark.style == CellStyle::reverse)
                boxed[pixel(mark)] = 1;
        }
        ++index;
    });
    std::vector<PixelMark> kept;
    index = 0;
    for_each_run_mark(runs, region, [&](const PixelMark& mark) {
        const std::uint32_t this_one = index++;
        if (!raster.contains(mark.at.x, mark.at.y)) {
            kept.push_back(mark);
            return;
        }
        if (last[pixel(mark)] != this_one)
            return;
        if (boxed[pixel(mark)] != 0 && mark.style != CellStyle::reverse)
            kept.push_back({mark.at, MarkKind::control_point, CellStyle::reverse, ColourRole::region});
        kept.push_back(mark);
    });
    return kept;
}

namespace {

void draw_staff(GraphicsScreen& screen, const PathScreenContent& content)
{
    for (const StaffLine line : staff_lines) {
        const int index = static_cast<int>(line);
        const int y = layout::staff_line_y(index);
        const int row = layout::first_staff_row + index;
        const bool active = content.active_line == line;
        screen.text.push_back({0, row, std::string(active ? ">" : " ") + std::string(staff_line_name(line)),
                               active ? CellStyle::reverse : CellStyle::plain});
        screen.ticked_lines.push_back({layout::staff_left, layout::staff_right, y,
                                       {layout::staff_x(-1.0), layout::staff_x(0.0), layout::staff_x(1.0)},
                                       layout::staff_tick_half_height});
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
    // In-betweens of an earlier state (exact spacing still measuring) would stand where none is.
    if (!path.inbetweens_current)
        return;
    for (const Inbetween& inbetween : path.inbetweens)
        screen.marks.push_back(
            {view.to_device(inbetween.position).rounded(), MarkKind::inbetween, CellStyle::plain, ColourRole::inbetween});
}

// Pre_Draw: every control point marked with an x; those of the picked region in reverse video.
void pre_draw(GraphicsScreen& screen, std::span<const PixelMark> marks)
{
    screen.marks.insert(screen.marks.end(), marks.begin(), marks.end());
}

// The picked region boxed on a terminal (pictures box each of its x's): a box a text cell outside
// its marks, on the boundary where it reaches it. Global
// control picks no region (every point is its own), so nothing is boxed there.
void box_region(GraphicsScreen& screen, const PathScreenContent& content)
{
    const std::optional<ControlRegion>& region = content.region;
    if (!region || (region->first == 0 && region->last + 1 >= content.control_points.size()))
        return;
    constexpr int far = std::numeric_limits<int>::max();
    PixelRect box{far, far, -far, -far};
    for (const PixelMark& mark : screen.marks) {
        if (mark.kind != MarkKind::control_point || mark.style != CellStyle::reverse ||
            !layout::inside_boundary.contains(mark.at))
            continue;
        box = {std::min(box.left, mark.at.x), std::min(box.top, mark.at.y), std::max(box.right, mark.at.x),
               std::max(box.bottom, mark.at.y)};
    }
    if (box.left == far)
        return;
    // Up to the boundary: the view area leaves one cell beside it, where a box around a point at
    // its edge must go rather than through the point.
    const PixelRect& area = layout::drawing_area;
    constexpr int across = hercules::cell_width;
    constexpr int down = hercules::cell_height + 1; // a text row is 14.5 pixels
    screen.boxes.push_back({std::max(box.left - across, area.left), std::max(box.top - down, area.top),
                            std::min(box.right + across, area.right - 1), std::min(box.bottom + down, area.bottom - 1)});
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


// The ghost dotted: its pixels in runs of 8 columns lit, 8 not (4 rows lit, 4 not; a diagonal
// about 3 and 3), so that the gaps are a braille dot or more wide at 80x24 and the ghost never
// reads as a second solid curve. Pixels the curve lights stay the curve's.
void draw_ghost(GraphicsScreen& screen, const Bitmap& ghost)
{
    Bitmap dotted;
    for (int y = layout::inside_boundary.top; y < layout::inside_boundary.bottom; ++y)
        for (int x = layout::inside_boundary.left; x < layout::inside_boundary.right; ++x)
            if (((x + 2 * y) / 8) % 2 == 0 && ghost.get(x, y))
                dotted.set(x, y, true);
    paint_layer(screen, dotted, ColourRole::ghost);
}

// A layer drawn inside the boundary on a raster of its own, then painted in its role: `draw` gets
// the layer's painter (recording strokes when the content asks).
template <typename Draw>
void inside_layer(GraphicsScreen& screen, const PathScreenContent& content, ColourRole role, Draw draw)
{
    Bitmap layer;
    Painter inside(layer, layout::inside_boundary);
    if (content.record_strokes)
        inside.record_into(screen.strokes);
    draw(inside);
    paint_layer(screen, layer, role);
}

void draw_tangents(GraphicsScreen& screen, const PathScreenContent& content, const ViewTransform& view)
{
    inside_layer(screen, content, ColourRole::tangent, [&](Painter& inside) {
        draw_tangent_arrows(screen, inside, content.path->curve.segments, view, *content.tangent_scale);
    });
    // An arrow's line is clipped at the boundary; its end mark must not sit on it or beside it.
    std::erase_if(screen.marks, [](const PixelMark& mark) {
        return mark.kind == MarkKind::tangent_end && !layout::view_area.contains(mark.at);
    });
}

// The screen, with the curve and the control points' marks either drawn here (kept == nullptr) or
// laid as an editor kept them.
GraphicsScreen draw_screen(const PathScreenContent& content, const ViewTransform& view, const KeptPathLayers* kept)
{
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    // Make_Boundary.
    if (content.record_strokes)
        painter.record_into(screen.strokes);
    painter.rectangle(layout::drawing_area);
    if (!content.key_frame_polylines.empty())
        inside_layer(screen, content, ColourRole::key_frame, [&](Painter& inside) {
            for (const auto& polyline : content.key_frame_polylines)
                draw_dotted(inside, polyline, view);
        });
    if (content.path != nullptr) {
        // DRAW: the KB curve, sampled.
        if (kept != nullptr && kept->ghost != nullptr)
            draw_ghost(screen, *kept->ghost);
        if (kept != nullptr && kept->reference != nullptr)
            draw_reference(screen, *kept->reference, kept->curve, kept->reference_label);
        if (kept != nullptr)
            paint_layer(screen, kept->curve, ColourRole::monitor);
        else
            inside_layer(screen, content, ColourRole::monitor,
                         [&](Painter& inside) { draw_world_curve(inside, content.path->curve, view); });
        draw_ani_path(screen, *content.path, view);
        // Tangents of segments not made yet would be those of an earlier state.
        if (content.tangent_scale && content.path->segments_unmade.empty())
            draw_tangents(screen, content, view);
    }
    if (kept != nullptr)
        pre_draw(screen, kept->control_point_marks);
    else
        pre_draw(screen, control_point_marks(control_point_runs(content.control_points, view), content.region));
    // A zoomed view (Z) leaves points beyond the boundary: their marks must not land on the staff.
    std::erase_if(screen.marks, [](const PixelMark& mark) {
        return (mark.kind == MarkKind::control_point || mark.kind == MarkKind::inbetween) &&
               !layout::inside_boundary.contains(mark.at);
    });
    box_region(screen, content);
    draw_arrow(screen, content, view);
    if (content.goal_point) {
        const PixelPoint at = view.to_device(*content.goal_point).rounded();
        if (layout::inside_boundary.contains(at))
            screen.marks.push_back({at, MarkKind::goal, CellStyle::reverse, ColourRole::goal});
    }
    draw_staff(screen, content);
    if (!content.message.empty())
        screen.text.push_back({1, layout::message_row, content.message});
    if (!content.key_help.empty())
        screen.text.push_back({1, layout::key_help_row, content.key_help});
    if (content.path != nullptr && content.law_span && content.path->inbetweens_current)
        draw_law_inset(screen, *content.path, *content.law_span);
    return screen;
}

} // namespace

GraphicsScreen draw_path_screen(const PathScreenContent& content, const ViewTransform& view)
{
    return draw_screen(content, view, nullptr);
}

GraphicsScreen draw_path_screen(const PathScreenContent& content, const ViewTransform& view, const KeptPathLayers& kept)
{
    return draw_screen(content, view, &kept);
}

} // namespace apcs
