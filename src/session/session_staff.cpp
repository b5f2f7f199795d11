// The graphics steps of the session: global or local control, picking the region, the four-line
// staff, accepting the path (thesis Check_GorL_Control, Scan_Control_Point, Scan_Parameters,
// tnextpixel, Ask_Adjusting).
#include "apcs/animation/control_region.h"
#include "apcs/formats/path_files.h"
#include "apcs/session/path_screen.h"
#include "apcs/session/session.h"
#include "apcs/session/session_text.h"
#include "session_keys.h"

namespace apcs {

namespace text = session_text;
using namespace session_keys;

void Session::handle_graphics_key(const KeyEvent& event)
{
    if (is_character(event, U'K', U'k')) {
        m_show_key_frames = !m_show_key_frames;
        return;
    }
    switch (m_phase) {
    case SessionPhase::choose_control:
        if (is_character(event, U'8') || event.key == Key::up) {
            m_region = {0, m_points[static_cast<std::size_t>(m_path)].size() - 1};
            m_files.log("global control");
            start_staff();
        } else if (is_character(event, U'2') || event.key == Key::down) {
            m_arrow.reset();
            m_phase = SessionPhase::pick_region_first;
        }
        return;
    case SessionPhase::pick_region_first:
        return handle_pick(event, false);
    case SessionPhase::pick_region_last:
        return handle_pick(event, true);
    case SessionPhase::staff:
        return handle_staff(event);
    case SessionPhase::ask_again:
        if (is_yes(event)) {
            m_phase = SessionPhase::choose_control;
            return;
        }
        accept_path();
        return;
    default:
        return;
    }
}

void Session::handle_pick(const KeyEvent& event, bool picking_last)
{
    const std::size_t last_index = m_points[static_cast<std::size_t>(m_path)].size() - 1;
    if (is_character(event, U'4') || event.key == Key::left) {
        m_arrow = m_arrow ? (*m_arrow > 0 ? *m_arrow - 1 : 0) : 0;
    } else if (is_character(event, U'6') || event.key == Key::right) {
        m_arrow = m_arrow ? std::min(*m_arrow + 1, last_index) : 0;
    } else if (event.key == Key::escape) {
        m_graphics_message.clear();
        m_phase = picking_last ? SessionPhase::pick_region_first : SessionPhase::choose_control;
    } else if (event.key == Key::enter && m_arrow) {
        if (!picking_last) {
            m_region_first = *m_arrow;
            m_graphics_message.clear();
            m_phase = SessionPhase::pick_region_last;
        } else if (*m_arrow <= m_region_first) {
            m_graphics_message = "The last control point must come after the first (point " +
                                 std::to_string(m_region_first + 1) + ")";
        } else {
            m_region = {m_region_first, *m_arrow};
            m_graphics_message.clear();
            m_files.log("local control: control points " + std::to_string(m_region.first + 1) + " to " +
                        std::to_string(m_region.second + 1));
            start_staff();
        }
    }
}

void Session::start_staff()
{
    m_staff = m_points[static_cast<std::size_t>(m_path)][m_region.first].staff;
    m_staff_line = 0;
    m_line_start_value = m_staff.tension;
    m_phase = SessionPhase::staff;
}

void Session::set_staff_value(double value)
{
    staff_value(m_staff, m_staff_line) = snapped(value);
    apply_staff_to_region();
}

void Session::apply_staff_to_region()
{
    apcs::apply_staff_to_region(m_points[static_cast<std::size_t>(m_path)], {m_region.first, m_region.second}, m_staff);
    reevaluate();
}

void Session::handle_staff(const KeyEvent& event)
{
    const double value = staff_value(m_staff, m_staff_line);
    const double step = m_settings.step;
    if (is_character(event, U'4') || event.key == Key::left)
        return set_staff_value(value - step);
    if (is_character(event, U'6') || event.key == Key::right)
        return set_staff_value(value + step);
    if (is_character(event, U'J', U'j'))
        return set_staff_value(value - 3 * step);
    if (is_character(event, U'L', U'l'))
        return set_staff_value(value + 3 * step);
    if (event.key != Key::enter && event.key != Key::escape)
        return;
    if (event.key == Key::escape)
        set_staff_value(m_line_start_value);
    m_files.log(std::string(staff_line_name(static_cast<StaffLine>(m_staff_line))) + " " +
                format_staff_value(staff_value(m_staff, m_staff_line)) + (event.key == Key::escape ? " (kept)" : ""));
    if (m_staff_line == 3) {
        m_phase = SessionPhase::ask_again;
        return;
    }
    ++m_staff_line;
    m_line_start_value = staff_value(m_staff, m_staff_line);
}

void Session::accept_path()
{
    const std::string& name = m_path_names[static_cast<std::size_t>(m_path)];
    if (auto problem = write_file(name, format_dat(dat_from(m_points[static_cast<std::size_t>(m_path)])))) {
        m_graphics_message = problem->to_string();
        m_phase = SessionPhase::ask_again;
        return;
    }
    record_written(name);
    m_files.log("accepted path " + name + " (rewritten with t c b a)");
    if (m_path == 0) {
        say(std::string(text::ask_next_path));
        m_phase = SessionPhase::ask_next_path;
    } else {
        say(std::string(text::ask_stop));
        m_phase = SessionPhase::ask_stop;
    }
}

} // namespace apcs
