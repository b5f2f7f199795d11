#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/control_point.h"
#include "apcs/animation/memory_budget.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/raster/png_encoder.h"
#include "apcs/session/animation_player.h"
#include "apcs/session/key_event.h"
#include "apcs/session/key_map.h"
#include "apcs/session/path_editor.h"
#include "apcs/session/session_files.h"
#include "apcs/session/session_phase.h"
#include "apcs/session/text_console.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_set>
#include <variant>
#include <vector>

namespace apcs {

struct SessionSettings {
    int samples_per_segment = 32;
    int inbetween_count = 12;
    Spacing spacing = Spacing::nearest;
    double step = 0.05; // staff step per key
    // What an empty answer takes where the command line gave it (--theta, --phi, --delay,
    // --slopes); else the thesis' example (30 40 200, 1 1).
    std::optional<double> theta_degrees;
    std::optional<double> phi_degrees;
    std::optional<int> delay_ms;
    std::optional<EndSlopes> slopes;
    // The staff values of path files with three columns (--tension, --continuity, --bias, --accel).
    StaffValues staff;
    // Where the overlay of all frames goes as a PNG when the animation ends, if anywhere: as the
    // monitor showed it (--png) and as the bare raster (--png-raw).
    std::optional<std::string> overlay_png;
    std::optional<std::string> overlay_png_raw;
    std::optional<std::string> overlay_svg; // the same as vector lines (--svg)
    // The memory one request may take (APCS_MEMORY_LIMIT): more points or samples are refused.
    std::uint64_t memory_limit_bytes = memory::default_limit_bytes;
};

// What the terminal shows now: the DOS text console or the graphics screen.
struct SessionScreen {
    bool graphics = false;
    CellGrid text;          // 80x24, when !graphics
    GraphicsScreen picture; // when graphics
};

// The 1989 session (thesis Ch. 4.2, the program animate.c; SPEC §3) as a pure state machine: key
// events in; screens, and file actions through SessionFiles, out. No terminal, no clock: the shell
// calls tick() every delay_ms() while animating().
//
// The session routes between three kinds of step, each owning its state: the text prompts (a
// table in session_steps.cpp: phase → prompt lines, default answer, what the answer does), the
// PathEditor of graphics mode and the AnimationPlayer. Keys become commands through the key map
// (key_map.h) in the context of the step on the screen.
class Session {
public:
    Session(SessionSettings settings, SessionFiles& files);

    void handle(const KeyEvent& event);
    void tick();

    SessionPhase phase() const;
    bool finished() const { return phase() == SessionPhase::finished; }
    bool animating() const;
    // The split is writing its path files, one per point (seconds for 10^5 points): the shell
    // calls work() until busy() is false, reading keys in between, so that Esc stops the split at
    // once. Each work() writes one batch of files; the screen shows how far the split is.
    bool busy() const { return m_split.has_value(); }
    void work();
    int delay_ms() const { return m_delay_ms; }
    SessionScreen screen() const;
    const std::vector<std::string>& written_files() const { return m_written; }
    // The last write that failed, if any did (the step that tried it was asked again).
    const std::optional<Diagnostic>& write_problem() const { return m_write_problem; }

private:
    // A step of the text console: a prompt, its answer and what follows.
    struct TextStep {
        SessionPhase current = SessionPhase::ask_key1;
        SessionPhase phase() const { return current; }
    };
    using Step = std::variant<TextStep, PathEditor, AnimationPlayer>;
    // One row of the prompt table: what the console prints when the step begins and again after
    // a wrong answer, the answer an empty line takes, and what the answer does.
    struct Prompt {
        SessionPhase phase;
        KeyContext keys;
        std::vector<std::string> (*lines)(const Session&);
        std::vector<std::string> (*again)(const Session&);
        std::string (*default_answer)(const Session&);
        void (Session::*submit)(const std::string& answer);
    };
    static const Prompt& prompt_for(SessionPhase phase);

    KeyContext key_context() const;
    KeyContext step_key_context() const;
    // Help, pictures and quitting: what any step may be asked (SPEC §3, §7.3). True when handled.
    bool handle_everywhere(KeyContext context, const Command& command);
    void dispatch_to_step(const Command& command);
    void update_text_step(SessionPhase phase, const Command& command);
    void save_picture();
    void write_overlay_once();
    // The picture as a PNG file; the message line says what happened.
    void write_picture(const std::string& name, const GraphicsScreen& picture, PngShape shape,
                       const std::string& log_line);
    void store_picture(const std::string& name, const std::string& bytes, const std::string& log_line);
    void quit();
    CellGrid help_screen() const;
    void go_to(SessionPhase phase);
    void ask_again(SessionPhase phase, const std::string& problem);

    // The text steps in the order of Ch. 4.2 (session_steps.cpp), named after animate.c.
    std::vector<std::string> key2_prompt() const;
    std::vector<std::string> view_prompt() const;
    std::string view_default() const;
    std::vector<std::string> done_lines() const;
    std::string path_file_default() const;
    std::string slopes_default() const;
    void read_key1(const std::string& name);
    void read_key2(const std::string& name);
    bool read_key_file(const std::string& name, int which);
    void add_points_and_split();
    void finish_split();
    void stop_split(const std::string&);
    // Ends the split's batch of writes: the one disk barrier for all its files. Its problem, if any
    // (remembered for write_problem() too).
    std::optional<Diagnostic> close_split();
    std::string split_progress() const;
    void define_view_parameters(const std::string& line);
    void read_data_file(const std::string& name);
    void predefine_ends_slope(const std::string& line);
    void initial_graphics();
    void accept_path(PathEditor& editor);
    std::string rewritten_path_file(const PathEditor& editor) const;
    void adjust_next_path(const std::string&);
    void surface_fitting(const std::string&);
    void showing_animation(const std::string&);
    void finish();

    PathSettings path_settings(int path) const;
    void say(const std::string& line) { m_console.print_line(line); }
    void record_written(const std::string& name);
    // Writes through SessionFiles, remembering a failure for write_problem().
    [[nodiscard]] std::optional<Diagnostic> write_file(const std::string& name, const std::string& content);

    SessionSettings m_settings;
    SessionFiles& m_files;
    TextConsole m_console;
    Step m_step;

    std::array<std::string, 2> m_key_names;
    std::array<Graphic, 2> m_key_frames;
    EqualisedKeys m_keys;
    std::size_t m_point_count = 0;
    // The split under way: the points of both keys, and how many path files are written.
    struct Split {
        std::vector<Vec3> key1;
        std::vector<Vec3> key2;
        std::size_t written = 0;
    };
    std::optional<Split> m_split;

    ViewAngles m_view_angles;
    int m_delay_ms = 200;

    // The path being asked for or shaped: 0, the first graphic point's; 1, the last's.
    int m_path = 0;
    std::array<std::string, 2> m_path_names;
    // The path files' text as read: accepting rewrites it with its comments.
    std::array<std::string, 2> m_path_texts;
    std::array<ControlPoints, 2> m_points;
    std::array<EndSlopes, 2> m_slopes;
    // DS[0] typed alone on its line, waiting for DD[N] (fig. 4.2.3).
    std::optional<double> m_first_slope;

    // The frames of surface fitting, kept until the animation shows them.
    FrameSequence m_fitted_frames;

    // The help screen is open over the step whose keys it lists.
    std::optional<KeyContext> m_help_for;
    // "Quit without saving this path ? (Y/N)" is asked.
    bool m_asking_quit = false;
    // What the last key did that the message line tells once (a picture written), if anything.
    std::string m_notice;
    bool m_overlay_written = false;

    std::vector<std::string> m_written;
    std::unordered_set<std::string> m_written_names; // m_written's, to find one among 10^6 at once
    std::optional<Diagnostic> m_write_problem;
};

} // namespace apcs
