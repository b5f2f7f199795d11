// What the path editor shows: the path screen of its step and the message line.
#include "apcs/session/path_editor.h"

#include "apcs/session/path_overlays.h"
#include "apcs/session/session_text.h"

namespace apcs {

namespace text = session_text;

std::string PathEditor::message() const
{
    if (!m_problem.empty())
        return m_problem;
    if (m_field)
        return m_field->message(staff_line_name(m_line));
    if (!m_notice.empty())
        return m_notice;
    switch (m_phase) {
    case SessionPhase::choose_control: return std::string(text::choose_control);
    case SessionPhase::pick_region_first: return std::string(text::pick_first);
    case SessionPhase::pick_region_last: return std::string(text::pick_last);
    case SessionPhase::staff:
        return m_show_tangents ? tangent_numbers(m_evaluated.curve.segments, m_tangent_point) : staff_message();
    default: return std::string(text::ask_again);
    }
}

std::string PathEditor::staff_message() const
{
    const std::string line(staff_line_name(m_line));
    // A path of two control points has no interior one, where t, c and b act: say so, or the
    // animator sees nothing move and cannot tell why.
    if (m_setup.points.size() == 2 && m_line != StaffLine::acceleration)
        return line + std::string(text::no_interior_points);
    const std::string of = " of " + std::to_string(m_setup.points.size());
    std::string message = m_setup.path_name + ": " + line;
    if (single_point_region())
        message += "  control point " + std::to_string(m_region.first + 1) + of + " (no span, no ACCELERATION)";
    else
        message += "  control points " + std::to_string(m_region.first + 1) + " to " +
                   std::to_string(m_region.last + 1) + of;
    if (m_evaluated.frames_freeze)
        message += "  (" + std::string(text::frames_freeze) + ")";
    return message;
}

// The span whose law G shows: the region's, the arrow's while picking, the chosen waypoint's.
std::size_t PathEditor::law_point() const
{
    if (m_waypoints)
        return m_waypoints->chosen();
    switch (m_phase) {
    case SessionPhase::staff:
    case SessionPhase::ask_again: return m_region.first;
    case SessionPhase::pick_region_first:
    case SessionPhase::pick_region_last: return m_arrow.value_or(0);
    default: return 0;
    }
}

// The region boxed: the one adjusted, or its first point while the last is picked.
std::optional<PickedRegion> PathEditor::picked_region() const
{
    switch (m_phase) {
    case SessionPhase::staff:
    case SessionPhase::ask_again: return PickedRegion{m_region.first, m_region.last};
    case SessionPhase::pick_region_last: return PickedRegion{m_region_first, m_region_first};
    default: return std::nullopt;
    }
}

PathScreenContent PathEditor::screen_content() const
{
    if (m_waypoints) {
        PathScreenContent content = path_screen_content(m_waypoints->points(), m_waypoints->evaluated());
        content.record_strokes = false;
        content.region = std::pair{m_waypoints->chosen(), m_waypoints->chosen()};
        content.arrow_at = m_waypoints->chosen();
        content.message = m_waypoints->message();
        return content;
    }
    PathScreenContent content = path_screen_content(m_setup.points, m_evaluated);
    content.curve_raster = &m_curve_raster;
    content.record_strokes = false;
    content.control_point_marks = m_point_marks;
    content.region = picked_region();
    if (m_phase == SessionPhase::staff || m_phase == SessionPhase::ask_again)
        content.staff = m_staff;
    if (m_phase == SessionPhase::staff)
        content.active_line = m_line;
    if (m_phase == SessionPhase::pick_region_first || m_phase == SessionPhase::pick_region_last) {
        content.arrow_at = m_arrow;
        content.arrow_home = !m_arrow.has_value();
    }
    content.message = message();
    return content;
}

GraphicsScreen PathEditor::view() const
{
    PathScreenContent content = screen_content();
    if (m_show_key_frames)
        content.key_frame_polylines = m_setup.key_frame_polylines;
    if (m_show_tangents)
        content.tangent_scale = m_tangent_scale;
    if (m_show_law)
        content.law_span = span_of_point(*content.path, law_point());
    content.key_help = key_help(key_context());
    return draw_path_screen(content, m_view);
}

} // namespace apcs
