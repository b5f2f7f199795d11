#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/view_transform.h"
#include "apcs/geometry/hercules.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/raster/painter.h"

#include <span>
#include <string>
#include <vector>

namespace apcs {

// Where every figure draws (raster pixels): text rows 2 … 20, under the title and above the legend.
inline constexpr PixelRect figure_area{0, hercules::text_row_top(2), hercules::screen_width,
                                       hercules::text_row_top(21)};
// The text row of a figure's legend; a second legend line goes on the row under it.
inline constexpr int figure_legend_row = 22;

// One curve of a figure: its control points with their t, c, b, its stroke and its label.
struct FigureCurve {
    std::string label;
    ControlPoints points;
    LineStyle style = LineStyle::solid;
};

struct CurveFigure {
    std::string file_name; // e.g. "fig-3-1-1.png"
    std::string title;
    std::vector<FigureCurve> curves;
};

// The thesis' figures 3.1.1–3.1.4: t = −1, 0, 1; c = −1, 0, 1; b = −1, 0, 1 (each overlaid on the
// same control points) and a mix of t, c and b.
std::vector<CurveFigure> thesis_curve_figures();

// A curve figure at 720x348: the curves seen face-on (θ = 0, Φ = 90), x at the control points,
// the title at the top and a legend naming each curve's stroke at the bottom.
GraphicsScreen draw_curve_figure(const CurveFigure& figure);

// All frames of an example overlaid, as in the thesis' figures 5.1–5.2, with a title; `still`
// objects (fitted apart, as Ch. 3.3 fits unrelated objects, and not moving) are drawn once, solid.
GraphicsScreen draw_frames_figure(const std::string& title, const FrameSequence& frames, const Graphic& structure,
                                  ViewAngles angles, std::span<const Graphic> still = {});

// Every frame of `frames` drawn as `structure` draws its points: KEY1 and KEY2 (the first and last
// frame) solid, the in-betweens dotted, so the keys stand out as in the thesis' fig. 5.1.
void draw_frames(Painter& painter, const FrameSequence& frames, const Graphic& structure, const ViewTransform& view);
// The legend of the strokes draw_frames draws.
inline constexpr const char* frames_legend = "solid: KEY1 and KEY2   dotted: the in-betweens";

// A key point a figure marks: a box around it, `label` beside it, and a legend line saying what it is.
struct FigureMark {
    std::string label; // e.g. "A"
    Vec3 position;
    std::string legend;
};

// One frame of a scene drawn solid, its key points marked and explained under it (the look of the
// thesis' fig. 3.3.3, the robot with its neck A and wrist B).
GraphicsScreen draw_marked_frame_figure(const std::string& title, std::span<const Vec3> points,
                                        const Graphic& structure, ViewAngles angles,
                                        std::span<const FigureMark> marks);

} // namespace apcs
