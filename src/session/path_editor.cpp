#include "apcs/session/path_editor.h"

#include "apcs/animation/input_limits.h"
#include "apcs/session/path_screen.h"
#include "apcs/session/screen_layout.h"
#include "apcs/session/session_text.h"
#include "apcs/session/world_drawing.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace apcs {

namespace text = session_text;

namespace {

// Keys add multiples of the step; rounding to 1e-9 keeps repeated steps from drifting.
double snapped(double value) { return limits::staff_value.clamp(std::round(value * 1e9) / 1e9); }

ViewTransform initial_view(const PathEditor::Setup& setup, const EvaluatedPath& path)
{
    PathScreenContent shown = path_screen_content(setup.points, path);
    shown.key_frame_polylines = setup.key_frame_polylines;
    return path_screen_scene(shown).fit(setup.view_angles, layout::view_area);
}

std::vector<std::size_t> origins_of(std::size_t point_count)
{
    std::vector<std::size_t> origins(point_count);
    std::iota(origins.begin(), origins.end(), std::size_t{0});
    return origins;
}

} // namespace

PathEditor::PathEditor(Setup setup, SessionLog& log)
    : m_setup(std::move(setup))
    , m_origins(origins_of(m_setup.points.size()))
    , m_log(log)
    , m_evaluated(evaluate_path(m_setup.points, m_setup.settings))
    , m_view(initial_view(m_setup, m_evaluated))
{
    assert(m_setup.points.size() >= 2);
}

KeyContext PathEditor::key_context() const
{
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
    if (std::holds_alternative<command::ToggleKeyFrames>(command)) {
        m_show_key_frames = !m_show_key_frames;
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

void PathEditor::check_global_or_local_control(const Command& command)
{
    if (std::holds_alternative<command::ChooseGlobal>(command)) {
        m_log.log("global control");
        start_staff(ControlRegion::whole(m_setup.points));
    } else if (std::holds_alternative<command::ChooseLocal>(command)) {
        m_arrow.reset();
        m_phase = SessionPhase::pick_region_first;
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
        } else if (*m_arrow <= m_region_first) {
            m_problem = "The last control point must come after the first (point " +
                        std::to_string(m_region_first + 1) + ")";
        } else {
            m_problem.clear();
            m_log.log("local control: control points " + std::to_string(m_region_first + 1) + " to " +
                      std::to_string(*m_arrow + 1));
            start_staff({m_region_first, *m_arrow});
        }
    }
}

void PathEditor::start_staff(ControlRegion region)
{
    assert(region.first < region.last && region.last < m_setup.points.size());
    m_region = region;
    m_staff = m_setup.points[region.first].staff;
    m_line = StaffLine::tension;
    m_line_start_value = m_staff[m_line];
    m_phase = SessionPhase::staff;
}

void PathEditor::set_staff_value(double value)
{
    m_staff[m_line] = snapped(value);
    apply_staff_to_region(m_setup.points, m_region, m_staff);
    m_evaluated = evaluate_path(m_setup.points, m_setup.settings);
}

// Scan_Tension_Value … Scan_Accerlation_Value: one line at a time; each key is one tnextpixel.
void PathEditor::scan_parameters(const Command& command)
{
    if (const auto* step = std::get_if<command::StaffStep>(&command))
        return set_staff_value(m_staff[m_line] + step->steps * m_setup.staff_step);
    const bool keep = std::holds_alternative<command::Keep>(command);
    if (!keep && !std::holds_alternative<command::Accept>(command))
        return;
    if (keep)
        set_staff_value(m_line_start_value);
    m_log.log(std::string(staff_line_name(m_line)) + " " + format_staff_value(m_staff[m_line]) + (keep ? " (kept)" : ""));
    if (is_last_staff_line(m_line)) {
        m_phase = SessionPhase::ask_again;
        return;
    }
    m_line = next_staff_line(m_line);
    m_line_start_value = m_staff[m_line];
}

PathEditor::Outcome PathEditor::ask_adjusting(const Command& command)
{
    if (std::holds_alternative<command::Yes>(command)) {
        m_phase = SessionPhase::choose_control;
        return Outcome::editing;
    }
    return std::holds_alternative<command::No>(command) ? Outcome::accepted : Outcome::editing;
}

std::string PathEditor::message() const
{
    if (!m_problem.empty())
        return m_problem;
    switch (m_phase) {
    case SessionPhase::choose_control: return std::string(text::choose_control);
    case SessionPhase::pick_region_first: return std::string(text::pick_first);
    case SessionPhase::pick_region_last: return std::string(text::pick_last);
    case SessionPhase::staff: return staff_message();
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
    std::string message = m_setup.path_name + ": " + line + "  control points " + std::to_string(m_region.first + 1) +
                          " to " + std::to_string(m_region.last + 1) + " of " + std::to_string(m_setup.points.size());
    if (m_evaluated.frames_freeze)
        message += "  (" + std::string(text::frames_freeze) + ")";
    return message;
}

GraphicsScreen PathEditor::view() const
{
    PathScreenContent content = path_screen_content(m_setup.points, m_evaluated);
    const bool adjusting = m_phase == SessionPhase::staff || m_phase == SessionPhase::ask_again;
    if (adjusting) {
        content.staff = m_staff;
        content.region = std::pair{m_region.first, m_region.last};
    }
    if (m_phase == SessionPhase::staff)
        content.active_line = m_line;
    if (m_phase == SessionPhase::pick_region_last)
        content.region = std::pair{m_region_first, m_region_first};
    if (m_phase == SessionPhase::pick_region_first || m_phase == SessionPhase::pick_region_last) {
        content.arrow_at = m_arrow;
        content.arrow_home = !m_arrow.has_value();
    }
    if (m_show_key_frames)
        content.key_frame_polylines = m_setup.key_frame_polylines;
    content.message = message();
    content.key_help = key_help(key_context());
    return draw_path_screen(content, m_view);
}

} // namespace apcs
