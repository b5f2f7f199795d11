#pragma once

#include "apcs/raster/png_encoder.h"
#include "apcs/input/interactive_program.h"
#include "apcs/formats/key_event.h"
#include "apcs/input/chart.h"
#include "apcs/input/overlays.h"
#include "apcs/session/session_files.h"
#include "apcs/session/session_model.h"
#include "apcs/session/session_settings.h"
#include "apcs/session/session_steps.h"
#include "apcs/screens/text_console.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace apcs {

// The 1989 session (thesis Ch. 4.2, the program animate.c; SPEC §3) as a pure state machine: key
// events in; screens, and file actions through SessionFiles, out. No terminal, no clock.
//
// The session holds the step on the screen (session_steps.h), the overlays over it (help, the
// quit question) and what the steps made (SessionModel). Keys become commands through the key
// map (key_map.h) in the keys of the chart's leaf; a row of the chart takes each, the step says
// how it ended, and the steps' graph (session_graph.cpp) says which step follows.
class Session final : public InteractiveProgram {
public:
    Session(SessionSettings settings, SessionFiles& files);

    // The session's chart (session_chart.cpp): the steps of thesis Ch. 4.2 as its leaves, the help
    // and the quit question laid over them, and the keys the session takes itself (?, P, q). The
    // path screen and the animation hand every other command to their own charts
    // (PathEditor::chart, AnimationPlayer::chart); how a step ends leads to the next by the steps'
    // graph (session_graph.cpp).
    enum class State {
        session,          // the root
        overlays,         // laid over the step, which stays underneath as it was; one alone takes keys
        help,             // ? or F1: the keys of the step, until any key
        quit_question,    // "Quit APCS ? (Y/N)", "Quit without saving this path ? (Y/N)"
        steps,            // the step on the screen: ?, P and q are the session's
        console,          // the text steps
        text_line,        // a prompt's line being typed
        ask_key1,         // step 1: the KEY1 file
        ask_key2,         // and KEY2
        splitting,        // the path files being written: Esc stops it
        ask_view,         // step 2: the view and the delay
        ask_path_file,    // step 3: a path file
        ask_slopes,       // and its end slopes
        question,         // a question waiting for one key
        ask_next_path,    // "Press 'Y' to adjust the next path !"
        ask_stop,         // "Press <ENTER> to Stop the work !"
        ask_draw,         // "Press any key ..." after surface fitting
        path_screen,      // steps 3-5 in graphics mode: the path editor's chart
        player,           // step 6, the animation: the player's chart
        finished,         // the end: nothing is read
    };
    using SessionChart = Chart<Session, State>;
    using StepGraph = Chart<Session, State, StepResult>;
    static const SessionChart& chart();
    static const StepGraph& graph();

    void handle(const KeyEvent& event) override;
    void tick() override;
    // The split writes its path files a batch per work() (seconds for 10^5 points), so that Esc
    // stops it at once; the screen shows how far it is. While a path is shaped, work() is a step of
    // its picture's refinement.
    void work() override;
    bool finished() const override { return std::holds_alternative<step::Finished>(m_step); }
    bool animating() const override;
    // The animation shows its frames, running or paused (not yet stopped at the last).
    bool showing_frames() const;
    // Busy while working() or preparing(): a step of either per work().
    bool busy() const override;
    // The step works between keys: a split, or the path editor refining its picture
    // (Refinement::in_steps). A replay waits for it before its next key.
    bool working() const;
    // At the slopes prompt of a long path, until its evaluation's arrays are made: work no key
    // waits for (a replay routes keys as at any prompt; the step that takes the answer takes the
    // arrays made so far).
    bool preparing() const { return path_wanting_room() != nullptr; }
    int delay_ms() const override { return m_model.delay_ms; }
    ProgramScreen screen() const override;
    // A key advances it when it changes what is shown: the path screen as its look compares, else
    // what the console, the overlays, the steps and the player count of their own changes, and the
    // message line; a key that changes nothing (a staff step past +1, a key no step takes, Backspace
    // on an empty answer) leaves it. A tick or a step of work always advances it.
    std::uint64_t screen_revision() const override { return m_revision; }

    // The leaf of the session's chart: an overlay's while one is open, else the step's.
    State leaf() const;
    // The step's leaf, under any overlay.
    State step_leaf() const;
    // The innermost leaf's name, the path editor's or the player's on their screens ("staff",
    // "running", "ask_view"), as the printed charts spell it.
    std::string_view leaf_name() const;
    // What a transcript and the help screen call the step ("step 4: four-line staff").
    std::string_view step_title() const;
    // The keys the session listens with now (an overlay's, else the step's).
    KeyContext key_context() const;
    // Whether the help (? or F1) is over the step: a whole screen of its own until a key closes it.
    bool showing_help() const;
    // Whether the step now takes typed text: a prompt's line, or a staff value after '='.
    bool takes_typed_text() const;
    // Whether `event`, typed now, is known to leave the step where it is (stays_in_step; a key
    // the step ignores stays too). False says nothing.
    bool keeps_step(const KeyEvent& event) const;
    const std::vector<std::string>& written_files() const { return m_model.written.names(); }
    // The KEY1 and KEY2 files as typed (empty until read), relative to the session's folder.
    const std::array<std::string, 2>& key_names() const { return m_model.key_names; }
    // The path being shaped (steps 3 to 5 of one path), none at any other step.
    const PathEditor* path_editor() const;
    // Which path path_editor() shapes: 0 the first graphic point's, 1 the last's (whatever file
    // was typed for it); none at any other step. An exercise's goal belongs to one of them.
    std::optional<int> shaped_path() const;
    // What a key may cost now, in the operations of a replay's work budget (SPEC §3.2): one, and
    // one more for each control point of the largest path the session holds (the one being shaped
    // included): a key re-evaluates, re-spaces or fits at most that many segments, each a bounded
    // number of samples. The count is the same on every machine; apcs grade stops a replay whose
    // keys have cost more than its budget.
    std::uint64_t key_work() const;
    // What `event`, typed now, may cost: a waypoint edit that stays in the editor costs two of the
    // curve's blocks (CurveRaster::block_segments) and a pass over a 64th of the points (the runs
    // renumbered, the points after it moved up), not the whole path; any other key key_work().
    std::uint64_t key_work(const KeyEvent& event) const;
    // The last write that failed, if any did (the step that tried it was asked again).
    const Expected<void>& writes() const { return m_model.written.outcome(); }
    // An exercise's goal point (GOAL NEAR, INBETWEEN) marked on the path screen, or none.
    void mark_goal(std::optional<Vec3> point);
    // An exercise's feedback ("GOAL: …", "GOAL REACHED: …") on the message line, below an open
    // field or question, an error and what the last key did (SPEC §7.3); empty for none. `briefly`
    // is it in a few words, beside the question after the staff where the whole does not fit.
    void say_goal(std::string feedback, std::string briefly = {});

private:
    // What the parts of the screen count of their own changes: the console's, the overlays', the
    // steps begun and the commands the player took, and the path editor's (its revision). A key
    // that advances none and says nothing new leaves the screen as it was.
    struct ChangeCounts {
        std::uint64_t console = 0;
        std::uint64_t overlays = 0;
        std::uint64_t steps = 0;
        std::uint64_t editor = 0;
        bool operator==(const ChangeCounts&) const = default;
    };
    ChangeCounts counted_changes() const;
    void take_key(const KeyEvent& event);
    // A command the path screen or the animation takes by its own chart (the session chart's rows).
    void update_step(const Command& command);
    StepContext context();
    // The path whose evaluation's arrays the slopes prompt makes while it waits, if any.
    SessionPath* path_wanting_room();
    const SessionPath* path_wanting_room() const;
    KeyContext step_key_context() const;
    static SessionChart make_chart();
    static std::vector<SessionChart::Row> any_step_rows();
    static std::vector<SessionChart::Row> console_rows();
    static StepGraph make_graph();
    // The graph's rows' action: the step `To` made from the step `From` on the screen.
    template <typename From, typename To>
    void make_step_after();
    // The rows' actions: the line typed, the answer (an empty line: the prompt's) submitted, a
    // question answered or the split stopped; what the step said, for follow().
    void type_into_line(char32_t character);
    void erase_last_typed();
    // The line typed, without the blanks around it.
    std::string typed_answer() const;
    void submit_line();
    void answer_question();
    std::string empty_answer();
    // Follows the steps' graph from the step on the screen for `result`.
    void follow(StepResult result);
    void ask(const std::string& problem);
    void open_help();
    void save_picture();
    void quit();
    ProgramScreen graphics_screen(GraphicsScreen picture) const;
    CellGrid console_screen() const;

    SessionSettings m_settings;
    SessionFiles& m_files;
    TextConsole m_console;
    SessionModel m_model;
    Step m_step;
    Overlays m_overlays;
    // What the last key did that the message line tells once (a picture written), if anything.
    std::string m_notice;
    std::optional<Vec3> m_goal_point;
    std::string m_goal_feedback;
    std::string m_goal_briefly;
    std::uint64_t m_revision = 0;
    std::uint64_t m_step_changes = 0;
    // How the step the last command answered ended (set by the chart's rows), for follow().
    StepResult m_step_result;
};

} // namespace apcs
