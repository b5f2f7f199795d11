#include "apcs/editor/waypoint_editor.h"

#include "apcs/animation/arc_length.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/formats/number_text.h"
#include "apcs/base/overloaded.h"
#include "apcs/raster/screen_layout.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace apcs {

WaypointEditor::WaypointEditor(PathDocument& document, PathPicture& picture, Setup setup)
    : m_document(&document)
    , m_picture(&picture)
    , m_setup(setup)
    , m_first_edit(document.edit_count())
{
    assert(points().size() >= 2);
    m_picture->box_region(ControlRegion{m_chosen, m_chosen});
}

// Every key starts afresh: what the last one said is gone, and the chosen point is boxed again.
template <typename Edit>
void WaypointEditor::taking(Edit edit)
{
    m_problem.clear();
    m_notice.clear();
    edit();
    m_picture->box_region(ControlRegion{m_chosen, m_chosen});
}

void WaypointEditor::choose(int by)
{
    taking([&] { m_chosen = wrapped_point(m_chosen, by, points().size()); });
}

void WaypointEditor::move(const command::MovePoint& move)
{
    taking([&] { move_point(move); });
}

void WaypointEditor::insert()
{
    taking([&] { insert_point(); });
}

void WaypointEditor::remove()
{
    taking([&] { delete_point(); });
}

void WaypointEditor::undo()
{
    taking([&] { undo_last(); });
}

void WaypointEditor::zoom()
{
    taking([&] { zoom_view(); });
}

void WaypointEditor::discard()
{
    taking([&] { discard_changes(); });
}

void WaypointEditor::discard_changes()
{
    // Each take-back taken by the picture before the next: far-apart edits taken together would
    // cover the span between them (10^6 points made again, not a few).
    while (change_count() > 0) {
        revert_last();
        m_picture->catch_up();
    }
    // Nothing was kept: no curve before a change is left to show.
    m_picture->drop_ghost();
}

void WaypointEditor::revert_last()
{
    // Only waypoint edits are made while the editor is open.
    const WaypointChange change = std::get<WaypointChange>(m_document->undo());
    m_chosen = std::min(change.index, points().size() - 1);
}

bool WaypointEditor::is_key_frame_point(std::size_t index)
{
    const bool first = index == 0;
    if (!first && index + 1 != points().size())
        return false;
    m_problem = "Control point " + std::to_string(index + 1) + " is " + (first ? "KEY1" : "KEY2") +
                "'s point: it is never moved or deleted";
    return true;
}

// Halfway to the neighbour after the chosen point, or before it when the last is chosen.
void WaypointEditor::insert_point()
{
    const bool last = m_chosen + 1 == points().size();
    const std::size_t from = last ? m_chosen - 1 : m_chosen;
    WaypointChange change;
    change.kind = WaypointChange::Kind::insert;
    change.index = from + 1;
    // The segment from the points, as the curve makes it (the curve's own may wait for a refinement).
    const HermiteSegment segment = kb_segment(points(), m_picture->settings().slopes, from);
    change.point = {halfway_along(std::span(&segment, 1), 0), points()[m_chosen].staff};
    m_document->apply(change);
    m_chosen = change.index;
}

void WaypointEditor::delete_point()
{
    if (is_key_frame_point(m_chosen))
        return;
    WaypointChange change;
    change.kind = WaypointChange::Kind::remove;
    change.index = m_chosen;
    change.point = points()[m_chosen];
    change.origin = origins()[m_chosen];
    m_document->apply(change);
    m_chosen = std::min(m_chosen, points().size() - 2);
}

void WaypointEditor::move_point(const command::MovePoint& move)
{
    if (is_key_frame_point(m_chosen))
        return;
    const ViewTransform& view = m_setup.view;
    WaypointChange change;
    change.kind = WaypointChange::Kind::move;
    change.index = m_chosen;
    change.offset = m_setup.step * (move.right * view.screen_right() + move.up * view.screen_up() +
                                    move.toward * view.toward_viewer());
    m_document->apply(change);
}

void WaypointEditor::undo_last()
{
    if (change_count() == 0) {
        m_problem = "Nothing to undo in the waypoint editor";
        return;
    }
    revert_last();
}

void WaypointEditor::zoom_view()
{
    m_zoom_level = next_zoom_level(m_zoom_level);
    const int factor = 1 << m_zoom_level;
    const Vec3 about = points()[m_chosen].position;
    m_picture->set_view(m_zoom_level == 0 ? m_setup.view : m_setup.view.zoomed(factor, about, layout::view_area));
    m_notice = m_zoom_level == 0 ? "zoom off: the view the editor opened with"
                                 : "zoom ×" + std::to_string(factor) + " about control point " +
                                       std::to_string(m_chosen + 1) + " (Z: more)";
}

std::string WaypointEditor::message() const
{
    if (!m_problem.empty())
        return m_problem;
    if (!m_notice.empty())
        return m_notice;
    const Vec3 from_centre = points()[m_chosen].position - m_setup.view.centre();
    const double depth = dot(from_centre, m_setup.view.toward_viewer());
    return "control point " + std::to_string(m_chosen + 1) + " of " + std::to_string(points().size()) +
           "  depth " + format_staff_value(depth);
}

double waypoint_step(const BoundingBox& shown)
{
    const double diagonal = shown.empty() ? 0.0 : length(shown.high() - shown.low());
    // A scene that is one point still needs a step that moves something.
    return diagonal > 0.0 ? diagonal / 100.0 : 0.01;
}

Vec3 halfway_along(std::span<const HermiteSegment> segments, std::size_t from)
{
    assert(from < segments.size());
    return segments[from].point_at(halfway_parameter(segments[from]));
}

} // namespace apcs
