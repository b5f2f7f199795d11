#include "apcs/editor/path_picture.h"

#include "apcs/raster/screen_layout.h"

#include <algorithm>
#include <limits>

namespace apcs {

PointsPicture::PointsPicture(const ControlPoints& shown_points, const PathSettings& settings, PictureRefinement refinement,
                             EvaluatedPath room)
    : m_points(&shown_points)
    , m_point_count(shown_points.size())
    , m_settings(settings)
    , m_refinement(refinement)
    , m_evaluated(std::move(room))
{
    evaluate_path(points(), settings, m_evaluated, refinement.when);
    refine_if_quick();
}

void PointsPicture::refresh(const PathChange& change, PointsBack back)
{
    if (!m_refinement.seen) {
        remake(change);
        return;
    }
    if (m_curve.drawn()) {
        m_ghost = m_curve.pixels();
        m_ghost_back = std::move(back);
    } else if (m_ghost && m_ghost_back) {
        // While the curve is drawn in steps the ghost kept before stays (the last curve drawn
        // whole): its path is now two changes back.
        m_ghost_back = [this_change = std::move(back), earlier = std::move(m_ghost_back)](ControlPoints& ghost_points) {
            this_change(ghost_points);
            earlier(ghost_points);
        };
    }
    remake(change);
}

void PointsPicture::remake_whole()
{
    drop_ghost();
    remake(PathChange{0, m_point_count, points().size(), PathChange::What::positions});
}

void PointsPicture::remake(const PathChange& change)
{
    m_point_count = points().size();
    ++m_revision;
    // A change of a step's segments or fewer (a local key, an acceleration, a waypoint edit) on a
    // refined path is evaluated at once: its first picture is its final one.
    const std::size_t segments =
        change.what == PathChange::What::accelerations ? 0 : std::max(change.removed, change.inserted) + 3;
    const bool quick = segments <= m_refinement.segments_a_step && m_evaluated.inbetweens_current;
    const Refinement when = quick ? Refinement::at_once : m_refinement.when;
    m_curve.splice(reevaluate_path(points(), m_settings, m_evaluated, change, when));
    refine_if_quick();
    if (!m_view || !m_refinement.seen)
        return;
    draw_curve();
    if (change.what != PathChange::What::positions)
        return;
    update_control_point_runs(m_point_runs, points(), *m_view, change);
    m_point_marks = control_point_marks(m_point_runs, m_region);
}

// Arc lengths left of no more than a step's segments (a path that short, or a local change over
// one that was) are measured at once; a global change's all wait for the steps.
void PointsPicture::refine_if_quick()
{
    if (m_evaluated.segments_unmade.empty() && m_evaluated.arc_lengths.segments_pending() <= m_refinement.segments_a_step)
        refine_path(points(), m_settings, m_evaluated, m_refinement.segments_a_step);
}

bool PointsPicture::refining() const { return !m_evaluated.inbetweens_current || curve_left(); }

bool PointsPicture::curve_left() const { return m_view && m_refinement.seen && !m_curve.drawn(); }

// The segments first, and the blocks they complete drawn; then the rest of the curve (the
// picture); then the arc lengths.
void PointsPicture::refine_step()
{
    ++m_revision;
    if (!m_evaluated.segments_unmade.empty()) {
        refine_path(points(), m_settings, m_evaluated, m_refinement.segments_made_a_step);
        if (m_view && m_refinement.seen)
            draw_curve();
    } else if (curve_left()) {
        draw_curve();
    } else {
        refine_path(points(), m_settings, m_evaluated, m_refinement.segments_a_step);
    }
}

void PointsPicture::refine()
{
    if (refining())
        ++m_revision;
    while (!refine_path(points(), m_settings, m_evaluated, std::numeric_limits<std::size_t>::max()))
        ;
    if (curve_left())
        m_curve.update(m_evaluated.curve, *m_view, layout::inside_boundary);
}

std::string PointsPicture::refining_message() const
{
    if (curve_left())
        return "drawing the curve: " + std::to_string(m_curve.blocks_drawn()) + " of " +
               std::to_string(m_curve.block_count()) + " blocks (keys are taken meanwhile)";
    if (!m_evaluated.inbetweens_current)
        return "measuring arc lengths for exact spacing: in-betweens shown when done";
    return {};
}

std::string PointsPicture::refining_words() const
{
    if (curve_left())
        return "drawing the curve";
    if (!m_evaluated.inbetweens_current)
        return "measuring arc lengths";
    return {};
}

void PointsPicture::set_view(const ViewTransform& view)
{
    ++m_revision;
    m_view = view;
    if (!m_refinement.seen)
        return;
    m_point_runs = control_point_runs(points(), *m_view);
    m_point_marks = control_point_marks(m_point_runs, m_region);
    draw_curve();
    draw_ghost();
    draw_reference();
}

namespace {

// The curve of `points` alone in `view`: no in-betweens, so no arc lengths (seconds on 10^6 points).
Bitmap curve_pixels(const ControlPoints& points, const PathSettings& settings, const ViewTransform& view)
{
    PathSettings curve_only = settings;
    curve_only.inbetween_count = 0;
    curve_only.spacing = Spacing::nearest;
    CurveRaster curve;
    curve.update(evaluate_path(points, curve_only).curve, view, layout::inside_boundary);
    return curve.pixels();
}

} // namespace

// The ghost's pixels in this view, from its path: the points now taken back over the last change.
void PointsPicture::draw_ghost()
{
    if (!m_ghost || !m_ghost_back)
        return;
    ControlPoints before = points();
    m_ghost_back(before);
    m_ghost = curve_pixels(before, m_settings, *m_view);
}

void PointsPicture::pin_reference(std::string label)
{
    ++m_revision;
    m_reference = Reference{points(), std::move(label), {}};
    if (!m_refinement.seen)
        return;
    // Pinned, the reference is the curve: its pixels are the curve's once drawn whole, and need not
    // be evaluated again (a second on 10^6 points).
    if (m_view && m_curve.drawn() && m_evaluated.segments_unmade.empty())
        m_reference->pixels = m_curve.pixels();
    else if (m_view)
        draw_reference();
}

bool PointsPicture::reference_under_curve() const
{
    const auto same_curve = [](const ControlPoint& a, const ControlPoint& b) {
        return a.position == b.position && a.staff.tension == b.staff.tension &&
               a.staff.continuity == b.staff.continuity && a.staff.bias == b.staff.bias;
    };
    return m_reference && std::equal(m_reference->points.begin(), m_reference->points.end(), points().begin(),
                                     points().end(), same_curve);
}

void PointsPicture::unpin_reference()
{
    if (m_reference)
        ++m_revision;
    m_reference.reset();
}

void PointsPicture::draw_reference()
{
    if (m_reference && m_refinement.seen)
        m_reference->pixels = curve_pixels(m_reference->points, m_settings, *m_view);
}

void PointsPicture::drop_ghost()
{
    if (m_ghost)
        ++m_revision;
    m_ghost.reset();
    m_ghost_back = nullptr;
}

void PointsPicture::box_region(std::optional<ControlRegion> region)
{
    if (region == m_region)
        return;
    ++m_revision;
    m_region = region;
    if (m_refinement.seen)
        m_point_marks = control_point_marks(m_point_runs, m_region);
}

void PointsPicture::draw_curve()
{
    m_curve.update(m_evaluated.curve, *m_view, layout::inside_boundary,
                   m_refinement.when == Refinement::at_once ? CurveRaster::all_work : m_refinement.drawing_a_step,
                   m_evaluated.segments_unmade);
}

GraphicsScreen PointsPicture::draw(const PathScreenContent& content) const
{
    const Bitmap* ghost = content.ghost && m_ghost ? &*m_ghost : nullptr;
    KeptPathLayers kept{m_curve.pixels(), m_point_marks, ghost, nullptr, {}};
    if (m_reference) {
        kept.reference = &m_reference->pixels;
        kept.reference_label = m_reference->label;
    }
    return draw_path_screen(content, *m_view, kept);
}

PathPicture::PathPicture(PathDocument& document, const PathSettings& settings, PictureRefinement refinement,
                         EvaluatedPath room)
    : m_document(&document)
    , m_document_revision(document.revision())
    , m_picture(document.points(), settings, refinement, std::move(room))
{
}

PointsPicture& PathPicture::current()
{
    if (m_document_revision == m_document->revision())
        return m_picture;
    if (std::optional<ChangesTaken> taken = m_document->take_changes(m_document_revision))
        m_picture.refresh(taken->change, std::move(taken->back));
    else
        m_picture.remake_whole();
    m_document_revision = m_document->revision();
    return m_picture;
}

} // namespace apcs
