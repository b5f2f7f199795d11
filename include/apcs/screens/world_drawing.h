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
    // The points, and the curves' control points (samples too: a segment's first and last).
    template <typename Visit>
    void for_each_control_point(const Visit& visit) const
    {
        for (const Vec3& point : m_points)
            visit(point);
        for (const SampledCurve* curve : m_curves) {
            for (const HermiteSegment& segment : curve->segments)
                visit(segment.start);
            if (!curve->segments.empty())
                visit(curve->segments.back().end);
        }
    }
    // The samples of every segment for which within(segment) is false.
    template <typename Within, typename Visit>
    void for_each_sample_beyond(const Within& within, const Visit& visit) const
    {
        for (const SampledCurve* curve : m_curves) {
            const auto per_segment = static_cast<std::size_t>(curve->samples_per_segment);
            for (std::size_t s = 0; s < curve->segments.size(); ++s)
                if (!within(curve->segments[s]))
                    for (std::size_t j = 0; j <= per_segment; ++j)
                        visit(curve->segment_sample(s, j));
        }
    }

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
