#pragma once

#include "apcs/raster/png_encoder.h"
#include "apcs/input/interactive_program.h"
#include "apcs/formats/key_event.h"
#include "apcs/input/chart.h"
#include "apcs/input/overlays.h"
#include "apcs/session/session_files.h"
#include "apcs/session/session_model.h"
#include "apcs/input/session_phase.h"
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
// map (key_map.h) in the context of the step; the step says how it ended, and the transition
// table (session_graph.cpp) says which step follows.
class Session final : public InteractiveProgram {
public:
    Session(SessionSettings settings, SessionFiles& files);

    // The text console's steps as a chart (session_console_chart.cpp): a prompt's line being typed
    // and answered, the questions that wait for Y, Enter or any key, and the split Esc stops.
    // Which step an answer leads to is the session's graph (session_graph.cpp); the path screen
    // and the animation are their own charts (PathEditor::chart, AnimationPlayer::chart).
    enum class ConsoleState {
        console,          // every text step
        text_line,        // KEY1, KEY2, the view, a path file, its slopes
        splitting,        // the path files being written
        question,         // the questions
        yes_question,     // "Press 'Y' to adjust the next path !"
        enter_question,   // "Press <ENTER> to Stop the work !"
        any_key_question, // "Press any key ..." on the console
    };
    using ConsoleChart = Chart<Session, ConsoleState>;
    static const ConsoleChart& console_chart();
    // The keys a leaf listens with.
    static KeyContext key_context_of(ConsoleState leaf);

    void handle(const KeyEvent& event) override;
    void tick() override;
    // The split writes its path files a batch per work() (seconds for 10^5 points), so that Esc
    // stops it at once; the screen shows how far it is. While a path is shaped, work() is a step of
    // its picture's refinement.
    void work() override;
    bool finished() const override { return phase() == SessionPhase::finished; }
    bool animating() const override;
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
    SessionScreen screen() const override;
    // A key that changes nothing on the path screen (a staff step past +1, a key no mode takes)
    // leaves it; any other key, tick or work advances it.
    std::uint64_t screen_revision() const override { return m_revision; }

    SessionPhase phase() const;
    // Whether the help (? or F1) is over the step: a whole screen of its own until a key closes it.
    bool showing_help() const;
    // Whether the step now takes typed text: a prompt's line, or a staff value after '='.
    bool takes_typed_text() const;
    // Whether `event`, typed now, is known to leave the step where it is (stays_in_phase; a key
    // the step ignores stays too). False says nothing.
    bool keeps_phase(const KeyEvent& event) const;
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
    // What the path screen shows, as far as a key can change it: compared before and after a key.
    struct ShapingLook {
        PathEditor::Look editor;
        std::string notice;
        bool overlaid = false;
        bool operator==(const ShapingLook&) const = default;
    };
    std::optional<ShapingLook> shaping_look() const;
    void take_key(const KeyEvent& event);
    StepContext context();
    // The path whose evaluation's arrays the slopes prompt makes while it waits, if any.
    SessionPath* path_wanting_room();
    const SessionPath* path_wanting_room() const;
    KeyContext step_key_context() const;
    void dispatch_to_step(const Command& command);
    // The text step on the screen as a leaf of the prompt chart.
    ConsoleState console_leaf() const;
    static ConsoleChart make_console_chart();
    // The rows' actions: the line typed, the answer (an empty line: the prompt's) submitted, a
    // question answered or the split stopped; what the step said, for follow().
    void type_into_line(char32_t character);
    void erase_last_typed();
    // The line typed, without the blanks around it.
    std::string typed_answer() const;
    void submit_line();
    void answer_question();
    std::string empty_answer();
    // Follows the transition table from the step on the screen for `result`.
    void follow(StepResult result);
    void ask(const std::string& problem);
    void save_picture();
    void quit();
    SessionScreen graphics_screen(GraphicsScreen picture) const;
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
    // How the text step the last command answered ended (console_chart's rows), for follow().
    StepResult m_console_result;
};

} // namespace apcs
