#include "apcs/raster/painter.h"
#include "apcs/session/path_screen.h"
#include "apcs/session/screen_layout.h"
#include "apcs/session/session.h"
#include "apcs/session/session_text.h"

namespace apcs {

namespace text = session_text;

namespace {

void draw_polyline(Painter& painter, const std::vector<Vec3>& polyline, const ViewTransform& view)
{
    if (polyline.size() == 1)
        painter.pixel(view.to_device(polyline.front()).rounded());
    for (std::size_t i = 1; i < polyline.size(); ++i)
        painter.line(view.to_device(polyline[i - 1]).rounded(), view.to_device(polyline[i]).rounded());
}

} // namespace

std::string Session::current_message() const
{
    if (!m_graphics_message.empty())
        return m_graphics_message;
    switch (m_phase) {
    case SessionPhase::choose_control:
        return std::string(text::choose_control);
    case SessionPhase::pick_region_first:
        return std::string(text::pick_first);
    case SessionPhase::pick_region_last:
        return std::string(text::pick_last);
    case SessionPhase::staff:
        return m_path_names[static_cast<std::size_t>(m_path)] + ": " +
               std::string(staff_line_name(static_cast<StaffLine>(m_staff_line))) +
               (m_evaluated.frames_freeze ? std::string("  (") + std::string(text::frames_freeze) + ")" : "");
    case SessionPhase::ask_again:
        return std::string(text::ask_again);
    default:
        return {};
    }
}

GraphicsScreen Session::path_picture() const
{
    PathScreenContent content;
    content.path = &m_evaluated;
    content.control_points = m_points[static_cast<std::size_t>(m_path)];
    const bool adjusting = m_phase == SessionPhase::staff || m_phase == SessionPhase::ask_again;
    content.staff = adjusting ? m_staff : content.control_points.front().staff;
    if (m_phase == SessionPhase::staff)
        content.active_line = static_cast<StaffLine>(m_staff_line);
    if (adjusting)
        content.region = m_region;
    else if (m_phase == SessionPhase::pick_region_last)
        content.region = std::pair{m_region_first, m_region_first};
    if (m_phase == SessionPhase::pick_region_first || m_phase == SessionPhase::pick_region_last) {
        content.arrow_at = m_arrow;
        content.arrow_home = !m_arrow.has_value();
    }
    if (m_show_key_frames) {
        for (const Graphic* key : {&m_keys.key1, &m_keys.key2}) {
            const std::vector<Vec3> points = key->all_points();
            for (auto& polyline : key->polylines(points))
                content.key_frame_polylines.push_back(std::move(polyline));
        }
    }
    content.message = current_message();
    content.key_help = m_phase == SessionPhase::staff ? std::string(text::staff_keys) + "  K key frames"
                                                      : std::string("K key frames on/off");
    return draw_path_screen(content, *m_view);
}

GraphicsScreen Session::animation_picture(bool all_frames) const
{
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    painter.rectangle(layout::drawing_area);
    const std::size_t first = all_frames ? 0 : m_frame;
    const std::size_t last = all_frames ? m_frames.frame_count() : std::min(m_frame + 1, m_frames.frame_count());
    for (std::size_t k = first; k < last && m_animation_view; ++k)
        for (const auto& polyline : m_keys.key1.polylines(m_frames.frame(k)))
            draw_polyline(painter, polyline, *m_animation_view);
    std::string message;
    if (m_phase == SessionPhase::animating)
        message = "Frame " + std::to_string(m_frame) + " of " + std::to_string(m_frames.frame_count() - 1) +
                  (m_paused ? "  (paused)" : "");
    else if (m_phase == SessionPhase::animation_done)
        message = std::string(text::animation_done);
    else
        message = std::string(text::overlay_done);
    screen.text.push_back({1, layout::message_row, message});
    if (m_phase == SessionPhase::animating)
        screen.text.push_back({1, layout::key_help_row, std::string(text::animation_keys)});
    return screen;
}

SessionScreen Session::screen() const
{
    SessionScreen shown;
    switch (m_phase) {
    case SessionPhase::choose_control:
    case SessionPhase::pick_region_first:
    case SessionPhase::pick_region_last:
    case SessionPhase::staff:
    case SessionPhase::ask_again:
        shown.graphics = true;
        shown.picture = path_picture();
        return shown;
    case SessionPhase::animating:
    case SessionPhase::animation_done:
        shown.graphics = true;
        shown.picture = animation_picture(false);
        return shown;
    case SessionPhase::overlay:
        shown.graphics = true;
        shown.picture = animation_picture(true);
        return shown;
    default:
        shown.text = m_console.render(m_phase != SessionPhase::finished);
        return shown;
    }
}

} // namespace apcs
