#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/sampled_curve.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/painter.h"

#include <span>
#include <vector>

namespace apcs {

// The world points a view must keep in sight (thesis VIEW_Transform is fitted to them), gathered
// from everything a screen will show.
class ViewScene {
public:
    ViewScene& add(std::span<const Vec3> points);
    // The control points' positions, visited where they are needed, never copied (a long path has
    // 10^6); the points must outlive the scene, and are visited before every other point.
    ViewScene& add(std::span<const ControlPoint> points);
    // Its samples, visited where they are needed, never gathered (a long path has 10^7); the
    // curve must outlive the scene.
    ViewScene& add(const SampledCurve& curve);
    ViewScene& add(const FrameSequence& frames);
    ViewScene& add(const std::vector<std::vector<Vec3>>& polylines);

    ViewTransform fit(ViewAngles angles, PixelRect drawing_area) const;
    // The view that fills `area` with the scene (ViewTransform::fill, SPEC §7.2.1): the same
    // viewpoint as fit's, the projection's extent (not its largest distance from the box's middle)
    // spread over the whole area. One pass over the points and the curves' control points, then the
    // samples of the segments that could reach further.
    ViewTransform fill(ViewAngles angles, PixelRect area) const;
    BoundingBox bounds() const;

private:
    // Each adds to `extent` what it reaches: reach(extent, point) for every point, and the extents
    // of a long list's two halves, gathered on both cores, joined in order (Extent::join keeps what
    // adding the second half's points one by one would keep: extremes are the same in any order,
    // and a tie keeps the earlier value). Visits the control points, the points, and the curves'
    // control points (samples too: a segment's first and last).
    template <typename Extent, typename Reach>
    void reach_control_points(Extent& extent, const Reach& reach) const;
    // The samples of every segment for which within(segment) is false.
    template <typename Extent, typename Within, typename Reach>
    void reach_samples_beyond(Extent& extent, const Within& within, const Reach& reach) const;

    std::vector<std::span<const ControlPoint>> m_control_points;
    std::vector<Vec3> m_points;
    std::vector<const SampledCurve*> m_curves;
};

// Projects a world polyline through `view` and strokes it; a polyline of one point is one pixel.
void draw_world_polyline(Painter& painter, std::span<const Vec3> polyline, const ViewTransform& view,
                         LineStyle style = LineStyle::solid);

// A graphic's parts at `points` (its own, or a frame's), each part a polyline as draw_world_polyline
// draws it (a closed part back to its first point).
void draw_world_graphic(Painter& painter, const Graphic& structure, std::span<const Vec3> points,
                        const ViewTransform& view, LineStyle style = LineStyle::solid);

// A sampled KB curve, drawn as draw_world_polyline draws its samples, except that a segment whose
// Bézier control points (P0, P0 + T0/3, P1 − T1/3, P1) all fall on the pixel where the line
// stands is passed over without projecting its samples: the segment lies in their hull, a
// perspective view keeps hulls, and a pixel is convex, so every sample would fall on that pixel
// and draw nothing. The same picture; for a long path (many segments on one pixel) far less work.
void draw_world_curve(Painter& painter, const SampledCurve& curve, const ViewTransform& view,
                      LineStyle style = LineStyle::solid);

} // namespace apcs
