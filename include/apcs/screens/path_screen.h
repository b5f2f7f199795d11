#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/control_region.h"
#include "apcs/animation/path_change.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/formats/number_text.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/screens/world_drawing.h"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// Control points that fall on one pixel one after another, first … last: the path screen marks
// them once (or once per part in and out of the picked region). A long trajectory of 10^6 control
// points has a few thousand runs; a path scribbled over the screen up to one per point.
struct ControlPointRun {
    PixelPoint at;
    std::size_t first = 0;
    std::size_t last = 0;
};
std::vector<ControlPointRun> control_point_runs(std::span<const ControlPoint> points, const ViewTransform& view);
// `runs` were control_point_runs of the points before `change`; `points` are those after it. Only
// the runs around the changed points are made again (a point moved among 10^6 projects a few), the
// runs after them renumbered; a change that moves no point changes no run.
void update_control_point_runs(std::vector<ControlPointRun>& runs, std::span<const ControlPoint> points,
                               const ViewTransform& view, const PathChange& change);

// The control points' marks, in reverse video inside `region`, one per pixel where they are many
// (a path of 10^6 control points scribbled over the screen has up to one per pixel, not 10^6):
// the cells and the picture show what a mark for every point would show.
std::vector<PixelMark> control_point_marks(std::span<const ControlPointRun> runs, std::optional<ControlRegion> region);

// Everything the path screen shows (thesis figs. 4.2.4–4.2.6).
struct PathScreenContent {
    const EvaluatedPath* path = nullptr;
    std::span<const ControlPoint> control_points;
    // The lines as vector strokes too, for SVG pictures; a terminal screen needs none (a long
    // scribbled path would hold one per pixel step).
    bool record_strokes = true;
    StaffValues staff;
    std::optional<StaffLine> active_line;
    // Local control: the picked region (first, last control point) drawn with a box around its x's.
    std::optional<ControlRegion> region;
    // Local control while picking: the arrow points at this control point.
    std::optional<std::size_t> arrow_at;
    // Before the first move the arrow waits at the top-left of the screen (thesis fig. 4.2.5).
    bool arrow_home = false;
    // Key frames drawn beside the path (thesis Ch. 6, item 2), dim: dotted.
    std::vector<std::vector<Vec3>> key_frame_polylines;
    // T: the tangents at every control point, drawn as tangent x this scale (path_overlays.h).
    std::optional<double> tangent_scale;
    // O: the ghost an editor kept (KeptPathLayers::ghost), drawn dotted.
    bool ghost = false;
    // G: the inset graph of this acceleration span's law.
    std::optional<std::size_t> law_span;
    // An exercise's goal point (GOAL NEAR, INBETWEEN), marked where the view shows it.
    std::optional<Vec3> goal_point;
    std::string message;
    std::string key_help;
};

// What a path screen shows of a path before any editing: its curve and shown in-betweens, its
// control points, and the first point's staff values.
PathScreenContent path_screen_content(std::span<const ControlPoint> points, const EvaluatedPath& path);

// The world points a path screen must keep in view (control points, curve, key frames).
ViewScene path_screen_scene(const PathScreenContent& content);

// Draws the path screen: boundary, curve, x at every control point, a dot at every shown
// in-between, the four-line staff with its values, the message and key lines.
GraphicsScreen draw_path_screen(const PathScreenContent& content, const ViewTransform& view);

// What an editor keeps between keys for the view it draws with, so that a long path is not
// projected again at every key (path_picture.h): the curve's pixels and the control points' marks
// (control_point_marks for the content's region).
struct KeptPathLayers {
    const Bitmap& curve;
    std::span<const PixelMark> control_point_marks;
    // The curve before the last change (SPEC §7.2.1), none if not shown.
    const Bitmap* ghost = nullptr;
    // The curve pinned by C and its label (SPEC §3.1, reference_curve.h), none if none is pinned.
    const Bitmap* reference = nullptr;
    std::string_view reference_label;
};
// The same screen with the curve and the control points' marks laid as kept.
GraphicsScreen draw_path_screen(const PathScreenContent& content, const ViewTransform& view, const KeptPathLayers& kept);

} // namespace apcs
