#include "apcs/session/path_picture.h"

#include "apcs/session/screen_layout.h"

namespace apcs {

PathPicture::PathPicture(std::span<const ControlPoint> points, const PathSettings& settings)
    : m_settings(settings)
    , m_evaluated(evaluate_path(points, settings))
{
}

void PathPicture::refresh(std::span<const ControlPoint> points, const PathChange& change, PointsBack back)
{
    m_ghost = m_curve.pixels();
    m_ghost_back = std::move(back);
    remake(points, change);
}

void PathPicture::refresh(std::span<const ControlPoint> points, const PathChange& change)
{
    drop_ghost();
    remake(points, change);
}

void PathPicture::remake(std::span<const ControlPoint> points, const PathChange& change)
{
    m_curve.splice(reevaluate_path(points, m_settings, m_evaluated, change));
    if (!m_view)
        return;
    draw_curve();
    if (change.what != PathChange::What::positions)
        return;
    update_control_point_runs(m_point_runs, points, *m_view, change);
    m_point_marks = control_point_marks(m_point_runs, m_region);
}

void PathPicture::set_view(std::span<const ControlPoint> points, const ViewTransform& view)
{
    m_view = view;
    m_point_runs = control_point_runs(points, *m_view);
    m_point_marks = control_point_marks(m_point_runs, m_region);
    draw_curve();
    draw_ghost(points);
}

// The ghost's pixels in this view, from its path: the points now taken back over the last change.
void PathPicture::draw_ghost(std::span<const ControlPoint> points)
{
    if (!m_ghost || !m_ghost_back)
        return;
    ControlPoints before(points.begin(), points.end());
    m_ghost_back(before);
    // Only the curve is drawn: no in-betweens, so no arc lengths (seconds on 10^6 points).
    PathSettings curve_only = m_settings;
    curve_only.inbetween_count = 0;
    curve_only.spacing = Spacing::nearest;
    CurveRaster ghost;
    ghost.update(evaluate_path(before, curve_only).curve, *m_view, layout::inside_boundary);
    m_ghost = ghost.pixels();
}

void PathPicture::drop_ghost()
{
    m_ghost.reset();
    m_ghost_back = nullptr;
}

void PathPicture::box_region(std::optional<ControlRegion> region)
{
    if (region == m_region)
        return;
    m_region = region;
    m_point_marks = control_point_marks(m_point_runs, m_region);
}

void PathPicture::draw_curve() { m_curve.update(m_evaluated.curve, *m_view, layout::inside_boundary); }

GraphicsScreen PathPicture::draw(const PathScreenContent& content) const
{
    const Bitmap* ghost = content.ghost && m_ghost ? &*m_ghost : nullptr;
    return draw_path_screen(content, *m_view, KeptPathLayers{m_curve.pixels(), m_point_marks, ghost});
}

} // namespace apcs
