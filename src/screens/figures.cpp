#include "apcs/screens/figures.h"

#include "apcs/animation/motion_path.h"
#include "apcs/screens/world_drawing.h"

namespace apcs {

namespace {

// The control points all curve figures share: a zigzag in the y-z plane, seen face-on.
ControlPoints zigzag(StaffValues staff)
{
    ControlPoints points;
    for (const Vec3& position : {Vec3{0, 0, 0}, Vec3{0, 3, 5}, Vec3{0, 7, 1}, Vec3{0, 10, 6}, Vec3{0, 14, 2}})
        points.push_back({position, staff});
    return points;
}

FigureCurve curve(const std::string& label, StaffValues staff, LineStyle style)
{
    return {label, zigzag(staff), style};
}

const char* style_name(LineStyle style)
{
    switch (style) {
    case LineStyle::solid: return "solid";
    case LineStyle::dashed: return "dashed";
    case LineStyle::dotted: return "dotted";
    }
    return "";
}

} // namespace

std::vector<CurveFigure> thesis_curve_figures()
{
    return {
        {"fig-3-1-1.png",
         "Fig. 3.1.1  Tension",
         {curve("t = -1", {-1, 0, 0, 0}, LineStyle::solid), curve("t = 0", {0, 0, 0, 0}, LineStyle::dashed),
          curve("t = 1", {1, 0, 0, 0}, LineStyle::dotted)}},
        {"fig-3-1-2.png",
         "Fig. 3.1.2  Continuity",
         {curve("c = -1", {0, -1, 0, 0}, LineStyle::solid), curve("c = 0", {0, 0, 0, 0}, LineStyle::dashed),
          curve("c = 1", {0, 1, 0, 0}, LineStyle::dotted)}},
        {"fig-3-1-3.png",
         "Fig. 3.1.3  Bias",
         {curve("b = -1", {0, 0, -1, 0}, LineStyle::solid), curve("b = 0", {0, 0, 0, 0}, LineStyle::dashed),
          curve("b = 1", {0, 0, 1, 0}, LineStyle::dotted)}},
        {"fig-3-1-4.png",
         "Fig. 3.1.4  Tension, continuity and bias together",
         {curve("t=0.5 c=-0.5 b=0", {0.5, -0.5, 0, 0}, LineStyle::solid),
          curve("t=-0.5 c=0 b=0.8", {-0.5, 0, 0.8, 0}, LineStyle::dashed),
          curve("t=0 c=0.7 b=-0.6", {0, 0.7, -0.6, 0}, LineStyle::dotted)}},
    };
}

GraphicsScreen draw_curve_figure(const CurveFigure& figure)
{
    std::vector<EvaluatedPath> paths;
    for (const FigureCurve& shown : figure.curves)
        paths.push_back(evaluate_path(shown.points, {{}, 48, 0, Spacing::nearest}));
    ViewScene scene;
    for (const EvaluatedPath& path : paths)
        scene.add(path.curve);
    const ViewTransform view = scene.fit({0, 90}, figure_area);
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    std::string legend;
    for (std::size_t i = 0; i < figure.curves.size(); ++i) {
        draw_world_curve(painter, paths[i].curve, view, figure.curves[i].style);
        legend += std::string(legend.empty() ? "" : "   ") + style_name(figure.curves[i].style) + ": " +
                  figure.curves[i].label;
    }
    if (!figure.curves.empty())
        for (const ControlPoint& point : figure.curves.front().points)
            painter.cross_marker(view.to_device(point.position).rounded());
    screen.text.push_back({1, 0, figure.title});
    screen.text.push_back({1, figure_legend_row, legend});
    return screen;
}

GraphicsScreen draw_frames_figure(const std::string& title, const FrameSequence& frames, const Graphic& structure,
                                  ViewAngles angles, std::span<const Graphic> still)
{
    ViewScene scene;
    scene.add(frames);
    for (const Graphic& object : still)
        scene.add(object.all_points());
    const ViewTransform view = scene.fit(angles, figure_area);
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    for (const Graphic& object : still)
        draw_world_graphic(painter, object, object.all_points(), view);
    draw_frames(painter, frames, structure, view);
    screen.text.push_back({1, 0, title});
    screen.text.push_back({1, figure_legend_row, std::string(frames_legend) +
                                              (still.empty() ? "" : "   the apple stands still")});
    return screen;
}

void draw_frames(Painter& painter, const FrameSequence& frames, const Graphic& structure, const ViewTransform& view)
{
    for (std::size_t k = 0; k < frames.frame_count(); ++k) {
        const LineStyle style = k == 0 || k + 1 == frames.frame_count() ? LineStyle::solid : LineStyle::dotted;
        draw_world_graphic(painter, structure, frames.frame(k), view, style);
    }
}

GraphicsScreen draw_marked_frame_figure(const std::string& title, std::span<const Vec3> points,
                                        const Graphic& structure, ViewAngles angles,
                                        std::span<const FigureMark> marks)
{
    const ViewTransform view = ViewScene().add(points).fit(angles, figure_area);
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    draw_world_graphic(painter, structure, points, view);
    int row = figure_legend_row;
    for (const FigureMark& mark : marks) {
        const PixelPoint at = view.to_device(mark.position).rounded();
        painter.rectangle({at.x - 4, at.y - 4, at.x + 5, at.y + 5}); // 9x9, centred
        // The letter sits right of the box and a little above it, where the thesis writes A and B.
        painter.text({at.x + 7, at.y - 16}, mark.label);
        screen.text.push_back({1, row++, mark.label + "  " + mark.legend});
    }
    screen.text.push_back({1, 0, title});
    return screen;
}

} // namespace apcs
