#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/input/chart.h"
#include "apcs/input/command.h"
#include "apcs/screens/frames_overlay.h"
#include "apcs/input/key_map.h"
#include "apcs/base/step_log.h"

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace apcs {

// Graphics mode after surface fitting (thesis Showing_Animation, SPEC §3 step 6): KEY1, each
// in-between and KEY2, one frame per tick, each erased before the next; Esc stops, Space pauses,
// R replays. After the last frame a key shows all frames overlaid (figs. 5.1–5.2) as
// frames_overlay_screen draws them (the first solid, the last dashed, the others dotted, a
// legend), and another ends the session. No clock: the shell calls tick() every delay while playing().
class AnimationPlayer {
public:
    enum class Outcome { showing, finished };
    // The player's states (its chart, animation_player_chart.cpp).
    enum class State {
        player,   // every state
        showing,  // the frames one at a time
        running,  // a frame a tick
        paused,   // Space, or a frame stepped with , and .
        stopped,  // the last frame (or Esc): a key overlays all frames
        overlaid, // all frames: a key ends the session
    };
    using PlayerChart = Chart<AnimationPlayer, State>;
    // Every row of the player: which command does what in which state.
    static const PlayerChart& chart();

    // `structure` gives the parts that draw each frame (the equalised KEY1); `key_names` name the
    // first and the last frame on the screen.
    AnimationPlayer(FrameSequence frames, Graphic structure, std::array<std::string, 2> key_names, ViewAngles angles,
                    int delay_ms, StepLog& log);

    Outcome update(const Command& command);
    void tick();
    // The screen: a frame, or after the last frame the overlay with the first, middle and last
    // frames (every frame is one blob at 80x24).
    GraphicsScreen view() const;
    // The overlay of every frame, as pictures (--png, --svg) draw it.
    GraphicsScreen overlay_picture() const;
    // What P writes: the screen, with every frame where the screen overlays three.
    GraphicsScreen picture() const;

    bool playing() const;
    // The keys the player listens with, and what a transcript calls its step: its leaf's.
    KeyContext key_context() const { return *chart().keys(leaf()); }
    std::string_view title() const { return chart().title(leaf()); }
    // The leaf of the chart the player is in.
    State leaf() const;

    // Which frame is shown, as the files are numbered: "KEY1: key1.dat", "In-between 3 of 12:
    // inb003.dat", "KEY2: key2.dat"; for a scene (name_frames_by_scene) "Frame 3 of 60: car.scn".
    std::string frame_label() const;
    // The frames are a scene's 0 … N (apcs play), named by their number and the scene's file, on
    // the screen and in the overlay's legend.
    void name_frames_by_scene(std::string scene_name);
    // Points the overlay of all frames marks and letters (a scene's timed waypoints), and the lines
    // under its legend that say what they are.
    void letter_points(std::vector<LetteredPoint> points, std::vector<std::string> notes);
    // A line shown on the message line instead of the frame's name until the next key (P's
    // "wrote apcs001.png" in apcs play).
    void show_notice(std::string notice) { m_notice = std::move(notice); }

private:
    FrameSequence m_frames;
    Graphic m_structure;
    std::array<std::string, 2> m_key_names;
    std::string m_scene_name;
    std::string m_notice;
    FramesOverlay m_overlay; // the legend's names, and lettered points
    ViewTransform m_view;
    StepLog& m_log;
    // The frames one at a time (Esc stops, Space pauses, R replays), the last frame shown until a
    // key, then all frames overlaid until a key ends it.
    struct Showing {
        bool paused = false;
    };
    struct Stopped {};
    struct Overlaid {};
    using Mode = std::variant<Showing, Stopped, Overlaid>;

    static PlayerChart make_chart();
    void step_frame(int by);
    void overlay_all_frames();
    std::string middle_frame_name() const;
    std::string message() const;

    Mode m_mode;
    std::size_t m_frame = 0; // the frame on the screen while showing or stopped
    // The command taken ended the session (a key at the overlay).
    bool m_finished = false;
};

} // namespace apcs
