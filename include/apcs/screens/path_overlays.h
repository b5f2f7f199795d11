#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/hermite.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/geometry/hercules.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/raster/painter.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

// What the path screen shows a class beside the 1989 picture (thesis Ch. 6's future work): the KB
// tangents at the control points (T) and the distance–time law of a span (G).
namespace apcs {

// The tangent arrows: at every control point DD_k leaves it (solid) and DS_k arrives at it
// (dashed), each drawn as the tangent times `scale` in world units, with a head at its tip and a
// `+` mark at its free end (DD's tip, DS's tail), the handles a class watches split and shrink.
// Each arrow is also kept in screen.arrows, so that a terminal lays it as characters (the lines
// and heads tell DD from DS without colour; the heads stand for the `+` marks there).
void draw_tangent_arrows(GraphicsScreen& screen, Painter& painter, std::span<const HermiteSegment> segments,
                         const ViewTransform& view, double scale);

// The scale of the arrows for the whole editing: the tangent's own length (an arrow is DS or DD as
// the message line gives its numbers; a Catmull-Rom tangent reaches about the next point), every
// arrow lengthened alike when the mean chord between control points is short on the screen, so
// that a back row can compare them. Fixed while the view is, so that arrows shrinking under
// tension are seen to shrink.
double tangent_arrow_scale(std::span<const ControlPoint> points, const ViewTransform& view);

// The message line's numbers of one control point (from 0), 1-based in the text:
// "point 2  DS 1.20 -0.40 0.00  DD 0.80 -0.27 0.00"; the first point has no DS, the last no DD.
std::string tangent_numbers(std::span<const HermiteSegment> segments, std::size_t point);

// Where the law graph may go: a box of 24 cells by 8 rows in one of the drawing area's four
// corners (top-right first), chosen to hide as little of the path as it can.
std::vector<PixelRect> law_inset_corners();

// The span of `path` whose law the inset shows for control point `point`: the one it starts or
// lies in (the last span for the last point). Nullopt when the path has no spans.
std::optional<std::size_t> span_of_point(const EvaluatedPath& path, std::size_t point);

// One in-between of a span on the law graph: its frame and its distance from the span's start,
// both as fractions of the span (frame j of m at j / (m + 1)); the distance is the in-between's
// own, so with the thesis' nearest samples a tick may sit just off the law's curve.
struct LawTick {
    double frame_fraction = 0.0;
    double distance_fraction = 0.0;
};
std::vector<LawTick> law_ticks(const EvaluatedPath& path, std::size_t span);

// Draws the inset over what is under it, in the corner that covers the fewest control points,
// then the fewest in-between marks, then the fewest lit pixels: a box with a title on its top edge
// (the span's acceleration), the law's curve (distance against frame, the axes named "distance"
// and "frame"), the in-betweens on it, and their distances as '-' ticks left of the distance axis,
// one a text row. Returns the box.
PixelRect draw_law_inset(GraphicsScreen& screen, const EvaluatedPath& path, std::size_t span);

} // namespace apcs
