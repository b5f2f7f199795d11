#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/control_point.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/session/key_event.h"
#include "apcs/session/session_files.h"
#include "apcs/session/text_console.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace apcs {

struct SessionSettings {
    int samples_per_segment = 32;
    int inbetween_count = 12;
    Spacing spacing = Spacing::nearest;
    double step = 0.05; // staff step per key
};

// The steps of thesis Ch. 4.2, one phase per prompt or screen.
enum class SessionPhase {
    ask_key1,
    ask_key2,
    ask_view,
    ask_path_file,
    ask_slopes,
    choose_control,
    pick_region_first,
    pick_region_last,
    staff,
    ask_again,
    ask_next_path,
    ask_stop,
    ask_draw,
    animating,
    animation_done,
    overlay,
    finished,
};

const char* phase_name(SessionPhase phase);

// What the terminal shows now: the DOS text console or the graphics screen.
struct SessionScreen {
    bool graphics = false;
    CellGrid text;          // 80x25, when !graphics
    GraphicsScreen picture; // when graphics
};

// The 1989 session as a pure state machine (SPEC §3): key events in; screens, and file actions
// through SessionFiles, out. No terminal, no clock: the shell calls tick() every delay_ms()
// while animating().
class Session {
public:
    Session(SessionSettings settings, SessionFiles& files);

    void handle(const KeyEvent& event);
    void tick();

    SessionPhase phase() const { return m_phase; }
    bool finished() const { return m_phase == SessionPhase::finished; }
    bool animating() const { return m_phase == SessionPhase::animating && !m_paused; }
    int delay_ms() const { return m_delay_ms; }
    SessionScreen screen() const;
    const std::vector<std::string>& written_files() const { return m_written; }

private:
    std::string default_answer() const;
    void start_path_prompt();
    void submit_line(const std::string& line);
    void submit_key_file(const std::string& name, int which);
    void finish_keys();
    void submit_view(const std::string& line);
    void submit_path_file(const std::string& name);
    void submit_slopes(const std::string& line);
    void enter_graphics();
    void handle_graphics_key(const KeyEvent& event);
    void handle_pick(const KeyEvent& event, bool picking_last);
    void handle_staff(const KeyEvent& event);
    void start_staff();
    void set_staff_value(double value);
    void apply_staff_to_region();
    void accept_path();
    void run_surface_fitting();
    void start_animation();
    // Path 0 (the first graphic point's) or 1 (the last's) with its slopes and the settings.
    EvaluatedPath evaluated(int path) const;
    void reevaluate();
    void say(const std::string& text);
    std::optional<Diagnostic> write_file(const std::string& name, const std::string& content);
    void record_written(const std::string& name);

    GraphicsScreen path_picture() const;
    GraphicsScreen animation_picture(bool all_frames) const;
    std::string current_message() const;

    SessionSettings m_settings;
    SessionFiles& m_files;
    SessionPhase m_phase = SessionPhase::ask_key1;
    TextConsole m_console;

    std::array<std::string, 2> m_key_names;
    std::array<Graphic, 2> m_key_frames;
    EqualisedKeys m_keys;
    std::size_t m_point_count = 0;

    ViewAngles m_view_angles;
    int m_delay_ms = 200;

    int m_path = 0; // 0: the first graphic point's path, 1: the last's
    std::array<std::string, 2> m_path_names;
    std::array<ControlPoints, 2> m_points;
    std::array<EndSlopes, 2> m_slopes;
    std::optional<double> m_first_slope;
    EvaluatedPath m_evaluated;
    std::optional<ViewTransform> m_view;
    bool m_show_key_frames = false;

    std::pair<std::size_t, std::size_t> m_region{0, 0};
    std::optional<std::size_t> m_arrow;
    std::size_t m_region_first = 0;
    int m_staff_line = 0;
    StaffValues m_staff;
    double m_line_start_value = 0.0;
    std::string m_graphics_message;

    FrameSequence m_frames;
    std::size_t m_frame = 0;
    bool m_paused = false;
    std::optional<ViewTransform> m_animation_view;

    std::vector<std::string> m_written;
};

} // namespace apcs
