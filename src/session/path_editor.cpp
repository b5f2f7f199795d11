#include "apcs/session/path_editor.h"

#include "apcs/animation/input_limits.h"
#include "apcs/session/path_overlays.h"
#include "apcs/session/screen_layout.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace apcs {

namespace {

// Keys add multiples of the step; rounding to 1e-9 keeps repeated steps from drifting.
double snapped(double value) { return limits::staff_value.clamp(std::round(value * 1e9) / 1e9); }

// What the view keeps in sight: the path, its control points and both key frames.
ViewScene shown_scene(const PathEditor::Setup& setup, const EvaluatedPath& path)
{
    PathScreenContent shown = path_screen_content(setup.points, path);
    shown.key_frame_polylines = setup.key_frame_polylines;
    return path_screen_scene(shown);
}

ViewTransform fitted_view(const PathEditor::Setup& setup, const EvaluatedPath& path)
{
    return shown_scene(setup, path).fit(setup.view_angles, layout::view_area);
}

// "1 change", "3 changes".
std::string changes_text(std::size_t count) { return std::to_string(count) + (count == 1 ? " change" : " changes"); }

} // namespace

PathEditor::PathEditor(Setup setup, SessionLog& log)
    : m_setup(std::move(setup))
    , m_origins(file_origins(m_setup.points.size()))
    , m_log(log)
    , m_evaluated(evaluate_path(m_setup.points, m_setup.settings))
    , m_view(fitted_view(m_setup, m_evaluated))
    , m_tangent_scale(tangent_arrow_scale(m_setup.points, m_view))
{
    assert(m_setup.points.size() >= 2);
    mark_control_points();
    m_curve_raster.update(m_evaluated.curve, m_view, layout::inside_boundary);
}

// Initial_Graphics fixes the view for the whole adjusting, so that each key's effect is seen
// against a still picture; the waypoint editor fits it again when it is left.
void PathEditor::fit_view()
{
    m_view = fitted_view(m_setup, m_evaluated);
    m_tangent_scale = tangent_arrow_scale(m_setup.points, m_view);
    mark_control_points();
}

// After the control points moved, were inserted or deleted: the whole path and its picture anew.
void PathEditor::evaluate_whole_path()
{
    evaluate_path(m_setup.points, m_setup.settings, m_evaluated);
    m_curve_raster.forget_all();
    mark_control_points();
}

// The control points or the view changed: their pixels, runs and marks anew.
void PathEditor::mark_control_points()
{
    m_point_runs = control_point_runs(m_setup.points, m_view);
    m_marks_region.reset();
    refresh_point_marks();
}

// The marks change with the picked region only: made again when it changes, not at every key.
void PathEditor::refresh_point_marks()
{
    const std::optional<PickedRegion> region = picked_region();
    if (m_marks_region && *m_marks_region == region)
        return;
    m_point_marks = control_point_marks(m_point_runs, region);
    m_marks_region = region;
}

SessionPhase PathEditor::phase() const { return m_waypoints ? SessionPhase::waypoints : m_phase; }

KeyContext PathEditor::key_context() const
{
    if (m_waypoints)
        return KeyContext::waypoints;
    if (m_field)
        return KeyContext::value_field;
    switch (m_phase) {
    case SessionPhase::choose_control: return KeyContext::control_choice;
    case SessionPhase::pick_region_first:
    case SessionPhase::pick_region_last: return KeyContext::region_pick;
    case SessionPhase::staff: return KeyContext::staff;
    default: return KeyContext::adjust_again;
    }
}

void PathEditor::show_problem(const std::string& message)
{
    m_problem = message;
    m_phase = SessionPhase::ask_again;
}

PathEditor::Outcome PathEditor::update(const Command& command)
{
    const Outcome outcome = take_command(command);
    m_curve_raster.update(m_evaluated.curve, m_view, layout::inside_boundary);
    refresh_point_marks();
    return outcome;
}

PathEditor::Outcome PathEditor::take_command(const Command& command)
{
    m_notice.clear();
    if (update_views(command))
        return Outcome::editing;
    if (m_waypoints) {
        update_waypoints(command);
        return Outcome::editing;
    }
    if (m_field) {
        update_value_field(command);
        return Outcome::editing;
    }
    if (std::holds_alternative<command::Undo>(command)) {
        undo();
        return Outcome::editing;
    }
    switch (m_phase) {
    case SessionPhase::choose_control: check_global_or_local_control(command); break;
    case SessionPhase::pick_region_first:
    case SessionPhase::pick_region_last: scan_control_point(command); break;
    case SessionPhase::staff: scan_parameters(command); break;
    default: return ask_adjusting(command);
    }
    return Outcome::editing;
}

// K, T, G and Tab change what is shown, never the path.
bool PathEditor::update_views(const Command& command)
{
    if (std::holds_alternative<command::ToggleKeyFrames>(command))
        m_show_key_frames = !m_show_key_frames;
    else if (std::holds_alternative<command::ToggleTangents>(command))
        m_show_tangents = !m_show_tangents;
    else if (std::holds_alternative<command::ToggleLawGraph>(command))
        m_show_law = !m_show_law;
    else if (const auto* choose = std::get_if<command::ChoosePoint>(&command); choose != nullptr && !m_waypoints)
        m_tangent_point = wrapped_point(m_tangent_point, choose->by, m_setup.points.size());
    else
        return false;
    return true;
}

void PathEditor::check_global_or_local_control(const Command& command)
{
    if (std::holds_alternative<command::ChooseGlobal>(command)) {
        m_log.log("global control");
        start_staff(ControlRegion::whole(m_setup.points));
    } else if (std::holds_alternative<command::ChooseLocal>(command)) {
        m_arrow.reset();
        m_phase = SessionPhase::pick_region_first;
    } else if (std::holds_alternative<command::OpenWaypoints>(command)) {
        open_waypoints();
    }
}

void PathEditor::scan_control_point(const Command& command)
{
    const bool picking_last = m_phase == SessionPhase::pick_region_last;
    const std::size_t last_index = m_setup.points.size() - 1;
    if (const auto* move = std::get_if<command::ArrowMove>(&command)) {
        // The arrow's first move, whichever way, brings it from the corner to the first point.
        const auto target = m_arrow ? static_cast<long long>(*m_arrow) + move->points : 0LL;
        m_arrow = static_cast<std::size_t>(std::clamp<long long>(target, 0, static_cast<long long>(last_index)));
    } else if (std::holds_alternative<command::Back>(command)) {
        m_problem.clear();
        m_phase = picking_last ? SessionPhase::pick_region_first : SessionPhase::choose_control;
    } else if (std::holds_alternative<command::Accept>(command) && m_arrow) {
        if (!picking_last) {
            m_region_first = *m_arrow;
            m_problem.clear();
            m_phase = SessionPhase::pick_region_last;
        } else if (*m_arrow < m_region_first) {
            m_problem = "The last control point must come after the first (point " +
                        std::to_string(m_region_first + 1) + ")";
        } else {
            // Enter twice on one control point picks it alone: KB's per-key control.
            m_problem.clear();
            m_log.log(*m_arrow == m_region_first
                          ? "local control: control point " + std::to_string(m_region_first + 1)
                          : "local control: control points " + std::to_string(m_region_first + 1) + " to " +
                                std::to_string(*m_arrow + 1));
            start_staff({m_region_first, *m_arrow});
        }
    }
}

void PathEditor::start_staff(ControlRegion region)
{
    assert(region.first <= region.last && region.last < m_setup.points.size());
    m_region = region;
    m_staff = m_setup.points[region.first].staff;
    m_line = StaffLine::tension;
    m_line_start_value = m_staff[m_line];
    m_tangent_point = region.is_whole(m_setup.points) ? 1 : region.first;
    m_phase = SessionPhase::staff;
}

// Every value that changes a point is one change for undo; a key that changes nothing (a step
// past the end of the line) is not.
void PathEditor::set_staff_value(double value)
{
    StaffChange change{m_region, m_line, m_staff, m_line_start_value, {}};
    m_staff[m_line] = snapped(value);
    change.points_before = apply_staff_to_region(m_setup.points, m_region, m_staff);
    if (m_staff == change.staff && staff_runs(m_setup.points, m_region) == change.points_before)
        return;
    const bool shape_changed = runs_change_shape(change.points_before, m_staff);
    m_history.push_back(std::move(change));
    reevaluate_region(m_region, shape_changed);
}

// A key changes the staff values of a region: only the segments their tangents shape are sampled
// again, and an acceleration alone moves only the in-betweens (a path of 10^6 control points stays
// interactive).
void PathEditor::reevaluate_region(ControlRegion region, bool shape_changed)
{
    if (!shape_changed) {
        place_inbetweens(m_setup.points, m_setup.settings, m_evaluated);
        return;
    }
    const SegmentRange remade = reevaluate_path(m_setup.points, m_setup.settings, m_evaluated, region.first, region.last);
    m_curve_raster.forget(remade.first, remade.end);
}

// Scan_Tension_Value … Scan_Accerlation_Value: one line at a time; each key is one tnextpixel.
void PathEditor::scan_parameters(const Command& command)
{
    if (const auto* step = std::get_if<command::StaffStep>(&command))
        return set_staff_value(m_staff[m_line] + step->steps * m_setup.staff_step);
    if (std::holds_alternative<command::OpenValueField>(command))
        m_field.emplace();
    else if (std::holds_alternative<command::Keep>(command))
        accept_staff_line(true);
    else if (std::holds_alternative<command::Accept>(command))
        accept_staff_line(false);
}

void PathEditor::accept_staff_line(bool keep)
{
    if (keep)
        set_staff_value(m_line_start_value);
    m_log.log(std::string(staff_line_name(m_line)) + " " + format_staff_value(m_staff[m_line]) + (keep ? " (kept)" : ""));
    // A single control point starts no span of its own: its acceleration line is skipped.
    const bool last_line = is_last_staff_line(m_line) || (single_point_region() && m_line == StaffLine::bias);
    if (last_line) {
        m_phase = SessionPhase::ask_again;
        return;
    }
    m_line = next_staff_line(m_line);
    m_line_start_value = m_staff[m_line];
}

// "=": the typed value sets the line like keys would; the line stays active.
void PathEditor::update_value_field(const Command& command)
{
    const ValueField::Outcome outcome = m_field->update(command);
    if (outcome == ValueField::Outcome::editing)
        return;
    if (outcome == ValueField::Outcome::set) {
        set_staff_value(m_field->value());
        m_log.log(std::string(staff_line_name(m_line)) + " typed " + format_staff_value(m_staff[m_line]));
        if (m_field->clamped())
            m_notice = std::string(staff_line_name(m_line)) + " set to " + format_staff_value(m_staff[m_line]) +
                       ": the staff runs from -1 to 1";
    }
    m_field.reset();
}

PathEditor::Outcome PathEditor::ask_adjusting(const Command& command)
{
    if (std::holds_alternative<command::Yes>(command)) {
        m_phase = SessionPhase::choose_control;
        return Outcome::editing;
    }
    return std::holds_alternative<command::No>(command) ? Outcome::accepted : Outcome::editing;
}

void PathEditor::undo()
{
    if (m_history.empty()) {
        m_notice = "Nothing to undo: the path is as it was opened";
        return;
    }
    const Change change = std::move(m_history.back());
    m_history.pop_back();
    m_problem.clear();
    std::visit([this](const auto& last) { undo_change(last); }, change);
    m_notice += "; " + changes_text(m_history.size()) + " left to undo";
    m_log.log(m_notice);
}

// Back to the staff line the change was made on, with the staff as it was.
void PathEditor::undo_change(const StaffChange& change)
{
    const bool shape_changed = runs_change_shape(change.points_before, m_setup.points[change.region.first].staff);
    restore_staff_runs(m_setup.points, change.region, change.points_before);
    reevaluate_region(change.region, shape_changed);
    m_region = change.region;
    m_staff = change.staff;
    m_line = change.line;
    m_line_start_value = change.line_start_value;
    m_phase = SessionPhase::staff;
    m_notice = "Undone: " + std::string(staff_line_name(change.line)) + " back to " +
               format_staff_value(change.staff[change.line]);
}

// A waypoint edit is undone at the choice of control, where the editor was opened.
void PathEditor::undo_change(const WaypointChange& change)
{
    revert_change(m_setup.points, m_origins, change);
    evaluate_whole_path();
    const std::string point = "control point " + std::to_string(change.index + 1);
    switch (change.kind) {
    case WaypointChange::Kind::insert: m_notice = "Undone: the insertion of " + point; break;
    case WaypointChange::Kind::remove: m_notice = "Undone: the deletion of " + point; break;
    case WaypointChange::Kind::move: m_notice = "Undone: the move of " + point; break;
    }
    m_tangent_point = std::min(m_tangent_point, m_setup.points.size() - 1);
    m_phase = SessionPhase::choose_control;
}

void PathEditor::open_waypoints()
{
    m_waypoints.emplace(WaypointEditor::Setup{m_setup.points, m_origins, m_setup.settings, m_view,
                                              waypoint_step(shown_scene(m_setup, m_evaluated).bounds())});
    m_log.log("waypoint editor");
}

void PathEditor::update_waypoints(const Command& command)
{
    const WaypointEditor::Outcome outcome = m_waypoints->update(command);
    if (outcome == WaypointEditor::Outcome::editing)
        return;
    const std::size_t changes = m_waypoints->changes().size();
    if (outcome == WaypointEditor::Outcome::kept) {
        m_history.insert(m_history.end(), m_waypoints->changes().begin(), m_waypoints->changes().end());
        m_setup.points = m_waypoints->points();
        m_origins = m_waypoints->origins();
        m_evaluated = m_waypoints->evaluated();
        m_curve_raster.forget_all();
        m_notice = "Waypoints: " + changes_text(changes) + " kept, " + std::to_string(m_setup.points.size()) +
                   " control points";
    } else {
        m_notice = "Waypoints: " + changes_text(changes) + " undone";
    }
    m_log.log(m_notice);
    m_waypoints.reset();
    m_tangent_point = std::min(m_tangent_point, m_setup.points.size() - 1);
    fit_view();
}

} // namespace apcs
