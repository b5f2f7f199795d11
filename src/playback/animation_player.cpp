#include "apcs/playback/animation_player.h"

#include "apcs/formats/path_files.h"
#include "apcs/screens/frames_overlay.h"
#include "apcs/raster/painter.h"
#include "apcs/base/overloaded.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/words.h"
#include "apcs/screens/world_drawing.h"

#include <algorithm>
#include <cassert>
#include <string>

namespace apcs {

namespace text = words;

namespace {

// Frame `k` alone, drawn by the parts of `structure`, inside the drawing area.
GraphicsScreen draw_frame(const FrameSequence& frames, const Graphic& structure, const ViewTransform& view,
                          std::size_t k)
{
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    painter.record_into(screen.strokes).rectangle(layout::drawing_area);
    Painter inside(screen.bitmap, layout::inside_boundary);
    inside.record_into(screen.strokes);
    if (k < frames.frame_count())
        for (const auto& polyline : structure.polylines(frames.frame(k)))
            draw_world_polyline(inside, polyline, view);
    return screen;
}

} // namespace

AnimationPlayer::AnimationPlayer(FrameSequence frames, Graphic structure, std::array<std::string, 2> key_names,
                                 ViewAngles angles, int delay_ms, StepLog& log)
    : m_frames(std::move(frames))
    , m_structure(std::move(structure))
    , m_key_names(std::move(key_names))
    , m_overlay{key_frames_names(m_key_names[0], m_key_names[1], m_frames.frame_count()), {}, {}, false, {}}
    , m_view(frames_view(m_frames, angles))
    , m_log(log)
    , m_mode(m_frames.frame_count() == 0 ? Mode(Stopped{}) : Mode(Showing{}))
{
    m_log.log("animation: " + std::to_string(m_frames.frame_count()) + " frames, " + std::to_string(delay_ms) +
              " ms each");
}

bool AnimationPlayer::playing() const
{
    const auto* showing = std::get_if<Showing>(&m_mode);
    return showing != nullptr && !showing->paused;
}

AnimationPlayer::State AnimationPlayer::leaf() const
{
    return std::visit(Overloaded{[](const Showing& showing) { return showing.paused ? State::paused : State::running; },
                                 [](const Stopped&) { return State::stopped; },
                                 [](const Overlaid&) { return State::overlaid; }},
                      m_mode);
}

// The row the command meets in the player's leaf (animation_player_chart.cpp).
AnimationPlayer::Outcome AnimationPlayer::update(const Command& command)
{
    m_notice.clear();
    m_finished = false;
    chart().fire(*this, command, [](const AnimationPlayer& player) { return player.leaf(); });
    return m_finished ? Outcome::finished : Outcome::showing;
}

// , and .: the frame before or after, paused there.
void AnimationPlayer::step_frame(int by)
{
    m_mode = Showing{true};
    m_frame = by < 0 ? (m_frame == 0 ? 0 : m_frame - 1) : std::min(m_frame + 1, m_frames.frame_count() - 1);
}

void AnimationPlayer::overlay_all_frames()
{
    m_mode = Overlaid{};
    m_log.log("showed all " + std::to_string(m_frames.frame_count()) + " frames overlaid");
}

std::string AnimationPlayer::frame_label() const
{
    if (!m_scene_name.empty())
        return "Frame " + std::to_string(m_frame) + " of " + std::to_string(m_frames.frame_count() - 1) + ": " +
               m_scene_name;
    if (m_frame == 0)
        return "KEY1: " + m_key_names[0];
    const std::size_t inbetweens = m_frames.frame_count() - 2;
    if (m_frame > inbetweens)
        return "KEY2: " + m_key_names[1];
    return "In-between " + std::to_string(m_frame) + " of " + std::to_string(inbetweens) + ": " +
           inbetween_file_name(m_frame);
}

// The overlay's middle frame as its legend names it: "frame 36", "in-between 6 (inb006.dat)".
std::string AnimationPlayer::middle_frame_name() const
{
    const std::size_t middle = m_frames.frame_count() > 0 ? (m_frames.frame_count() - 1) / 2 : 0;
    if (!m_scene_name.empty())
        return "frame " + std::to_string(middle);
    return "in-between " + std::to_string(middle) + " (" + inbetween_file_name(middle) + ")";
}

GraphicsScreen AnimationPlayer::picture() const
{
    return std::holds_alternative<Overlaid>(m_mode) ? overlay_picture() : view();
}

GraphicsScreen AnimationPlayer::overlay_picture() const
{
    return frames_overlay_screen(m_frames, m_structure, m_view, message(), m_overlay);
}

void AnimationPlayer::tick()
{
    if (!playing())
        return;
    if (m_frame + 1 < m_frames.frame_count())
        ++m_frame;
    else
        m_mode = Stopped{};
}

GraphicsScreen AnimationPlayer::view() const
{
    assert(m_frames.frame_count() == 0 || m_frame < m_frames.frame_count());
    if (std::holds_alternative<Overlaid>(m_mode)) {
        FramesOverlay on_terminal = m_overlay;
        on_terminal.first_middle_last = true;
        on_terminal.middle_name = middle_frame_name();
        return frames_overlay_screen(m_frames, m_structure, m_view, message(), on_terminal);
    }
    GraphicsScreen screen = draw_frame(m_frames, m_structure, m_view, m_frame);
    screen.text.push_back({1, layout::message_row, message()});
    if (std::holds_alternative<Showing>(m_mode))
        screen.text.push_back({1, layout::key_help_row, key_help(KeyContext::animation)});
    return screen;
}

void AnimationPlayer::name_frames_by_scene(std::string scene_name)
{
    m_scene_name = std::move(scene_name);
    m_overlay.names = scene_frames_names(m_frames.frame_count());
}

void AnimationPlayer::letter_points(std::vector<LetteredPoint> points, std::vector<std::string> notes)
{
    m_overlay.points = std::move(points);
    m_overlay.notes = std::move(notes);
}

std::string AnimationPlayer::message() const
{
    if (!m_notice.empty())
        return m_notice;
    return std::visit(Overloaded{[&](const Showing& showing) { return frame_label() + (showing.paused ? "  (paused)" : ""); },
                                 [](const Stopped&) { return std::string(text::animation_done); },
                                 [](const Overlaid&) { return std::string(text::overlay_done); }},
                      m_mode);
}

} // namespace apcs
