// The figures of the thesis' surface fitting (Ch. 3.2, fig. 3.2.1; SPEC §5.3, §5.3.1).
#include "apcs/screens/surface_figures.h"

#include "apcs/animation/surface_fit.h"
#include "apcs/screens/figures.h"
#include "apcs/screens/world_drawing.h"

#include <algorithm>
#include <string>

namespace apcs {

namespace {

constexpr int samples_per_line = 32;

// Points of `equalised` that `original` does not have: Algorithm 2 keeps the original points
// exactly, so whatever else is there it added.
std::vector<Vec3> points_added(const Graphic& original, const Graphic& equalised)
{
    const std::vector<Vec3> had = original.all_points();
    std::vector<Vec3> added;
    for (const Vec3& point : equalised.all_points())
        if (std::find(had.begin(), had.end(), point) == had.end())
            added.push_back(point);
    return added;
}

std::size_t choose_point_a(const EqualisedKeys& keys, const std::vector<Vec3>& added)
{
    const std::vector<Vec3> key1 = keys.key1.all_points();
    const std::vector<Vec3> key2 = keys.key2.all_points();
    const auto is_added = [&](const Vec3& point) {
        return std::find(added.begin(), added.end(), point) != added.end();
    };
    for (std::size_t i = 1; i + 1 < key1.size(); ++i)
        if (is_added(key1[i]) || is_added(key2[i]))
            return i;
    return key1.size() / 2;
}

std::vector<std::vector<Vec3>> v_lines_of(const std::vector<HermiteSegment>& u_lines, const Graphic& structure)
{
    std::vector<std::vector<Vec3>> lines;
    for (const double u : {0.25, 0.5, 0.75}) {
        std::vector<Vec3> across;
        for (const HermiteSegment& path : u_lines)
            across.push_back(path.point_at(u));
        for (std::vector<Vec3>& polyline : structure.polylines(across))
            lines.push_back(std::move(polyline));
    }
    return lines;
}

std::vector<SampledCurve> sampled(const std::vector<HermiteSegment>& segments)
{
    std::vector<SampledCurve> curves;
    for (const HermiteSegment& segment : segments)
        curves.push_back(sample_curve(std::span(&segment, 1), samples_per_line));
    return curves;
}

void draw_polylines(Painter& painter, const std::vector<std::vector<Vec3>>& polylines, const ViewTransform& view,
                    LineStyle style)
{
    for (const std::vector<Vec3>& polyline : polylines)
        draw_world_polyline(painter, polyline, view, style);
}

// A label beside a point, right of it and a little above, where the thesis writes A and B.
void label(Painter& painter, const ViewTransform& view, const Vec3& position, const std::string& name)
{
    const PixelPoint at = view.to_device(position).rounded();
    painter.text({at.x + 5, at.y - 16}, name);
}

Graphic open_graphic(std::vector<Vec3> points)
{
    return {{{"curve", Closure::open, std::move(points)}}};
}

EvaluatedPath path_through(std::initializer_list<Vec3> positions, const PathSettings& settings)
{
    ControlPoints points;
    for (const Vec3& position : positions)
        points.push_back({position, {}});
    return evaluate_path(points, settings);
}

// An added point's `x`, 7x7 pixels: larger than a control point's so that it shows on a key's line.
void added_mark(Painter& painter, PixelPoint centre)
{
    painter.line({centre.x - 3, centre.y - 3}, {centre.x + 3, centre.y + 3});
    painter.line({centre.x - 3, centre.y + 3}, {centre.x + 3, centre.y - 3});
}

// The strokes of fig. 3.2.1, the surface first so that the keys and the paths draw over it.
void draw_ferguson_strokes(Painter& painter, const SurfaceFigureSource& source, const FergusonFigure& figure,
                           const ViewTransform& view)
{
    const std::vector<SampledCurve> u_lines = sampled(figure.u_lines);
    for (std::size_t i = 0; i < u_lines.size(); ++i)
        draw_world_curve(painter, u_lines[i], view, i == figure.point_a ? LineStyle::solid : LineStyle::dotted);
    draw_polylines(painter, figure.v_lines, view, LineStyle::dotted);
    for (const EvaluatedPath* edge : {&source.first_path, &source.last_path})
        draw_world_curve(painter, edge->curve, view, LineStyle::dashed);
    for (const Graphic* key : {&source.keys.key1, &source.keys.key2})
        draw_world_graphic(painter, *key, key->all_points(), view);
    for (const Vec3& point : figure.added_points)
        added_mark(painter, view.to_device(point).rounded());
    for (const Vec3& point : figure.a_inbetweens)
        painter.dot_marker(view.to_device(point).rounded());
}

void draw_ferguson_labels(Painter& painter, const SurfaceFigureSource& source, const FergusonFigure& figure,
                          const ViewTransform& view)
{
    const Graphic& key1 = source.keys.key1;
    const Graphic& key2 = source.keys.key2;
    label(painter, view, key1.first_point(), "1");
    label(painter, view, key2.first_point(), "2");
    label(painter, view, key1.last_point(), "3");
    label(painter, view, key2.last_point(), "4");
    const Vec3 a = key1.all_points()[figure.point_a];
    const Vec3 b = key2.all_points()[figure.point_a];
    label(painter, view, a, "A");
    label(painter, view, b, "B");
    // The other added points as the thesis names KEY1's second one: A1, A2, …
    int other = 0;
    for (const Vec3& point : figure.added_points)
        if (point != a && point != b)
            label(painter, view, point, "A" + std::to_string(++other));
}

} // namespace

FergusonFigure ferguson_figure(const SurfaceFigureSource& source)
{
    FergusonFigure figure;
    std::vector<Vec3> added = points_added(source.key1, source.keys.key1);
    for (const Vec3& point : points_added(source.key2, source.keys.key2))
        added.push_back(point);
    figure.added_points = std::move(added);
    const std::vector<Vec3> key1 = source.keys.key1.all_points();
    const std::vector<Vec3> key2 = source.keys.key2.all_points();
    const Closure closure = source.keys.key1.is_closed() ? Closure::closed : Closure::open;
    const FergusonCorners corners{edge_tangents_of(source.first_path), edge_tangents_of(source.last_path)};
    figure.u_lines = ferguson_point_paths(key1, key2, closure, corners);
    figure.v_lines = v_lines_of(figure.u_lines, source.keys.key1);
    figure.point_a = choose_point_a(source.keys, figure.added_points);
    const FrameSequence frames =
        fit_key_frames(source.keys, source.first_path, source.last_path, SurfaceConstruction::ferguson);
    for (std::size_t k = 1; k + 1 < frames.frame_count(); ++k)
        figure.a_inbetweens.push_back(frames.frame(k)[figure.point_a]);
    return figure;
}

ViewTransform ferguson_figure_view(const SurfaceFigureSource& source, const FergusonFigure& figure,
                                   ViewAngles angles)
{
    const std::vector<SampledCurve> u_lines = sampled(figure.u_lines);
    ViewScene scene;
    scene.add(source.first_path.curve).add(source.last_path.curve);
    for (const SampledCurve& line : u_lines)
        scene.add(line);
    const std::vector<Vec3> key1 = source.keys.key1.all_points();
    const std::vector<Vec3> key2 = source.keys.key2.all_points();
    return scene.add(key1).add(key2).fit(angles, figure_area);
}

SurfaceFigureSource thesis_surface_example(const PathSettings& settings)
{
    const Graphic key1 = open_graphic({{0, 0, 0}, {0, 4, 1.5}, {0, 8, -1}, {0, 12, 0}});
    const Graphic key2 =
        open_graphic({{0, 0, 10}, {0, 2.5, 11.5}, {0, 5, 10.5}, {0, 7.5, 12}, {0, 10, 11}, {0, 12, 10}});
    return {key1, key2, equalise_key_frames(key1, key2), path_through({{0, 0, 0}, {2, -3, 5}, {0, 0, 10}}, settings),
            path_through({{0, 12, 0}, {-2, 15, 5}, {0, 12, 10}}, settings)};
}

GraphicsScreen draw_ferguson_figure(const std::string& title, const SurfaceFigureSource& source, ViewAngles angles)
{
    const FergusonFigure figure = ferguson_figure(source);
    const ViewTransform view = ferguson_figure_view(source, figure, angles);
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    draw_ferguson_strokes(painter, source, figure, view);
    draw_ferguson_labels(painter, source, figure, view);
    screen.text.push_back({1, 0, title});
    screen.text.push_back(
        {1, figure_legend_row, "solid: KEY1 (1 A 3), KEY2 (2 B 4), the path of A to B (dots: its in-betweens)"});
    screen.text.push_back(
        {1, figure_legend_row + 1, "dashed: the edge paths   dotted: the surface's u and v lines   x: added points"});
    return screen;
}

GraphicsScreen draw_surfaces_figure(const std::string& title, const SurfaceFigureSource& source, ViewAngles angles)
{
    const FrameSequence blend = fit_key_frames(source.keys, source.first_path, source.last_path);
    const FrameSequence ferguson =
        fit_key_frames(source.keys, source.first_path, source.last_path, SurfaceConstruction::ferguson);
    constexpr int middle = hercules::screen_width / 2;
    const PixelRect left{figure_area.left, figure_area.top, middle, figure_area.bottom};
    const PixelRect right{middle, figure_area.top, figure_area.right, figure_area.bottom};
    ViewScene scene;
    scene.add(blend).add(ferguson);
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    draw_frames(painter, blend, source.keys.key1, scene.fit(angles, left));
    draw_frames(painter, ferguson, source.keys.key1, scene.fit(angles, right));
    painter.line({middle, figure_area.top}, {middle, figure_area.bottom - 1});
    screen.text.push_back({1, 0, title});
    screen.text.push_back({1, 1, "--surface blend (the default)"});
    screen.text.push_back({hercules::text_columns / 2 + 1, 1, "--surface ferguson (the thesis)"});
    screen.text.push_back({1, figure_legend_row, frames_legend});
    return screen;
}

} // namespace apcs
