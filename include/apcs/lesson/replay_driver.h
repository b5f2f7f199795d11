#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/key_script.h"
#include "apcs/lesson/replay_pace.h"
#include "apcs/formats/key_recording.h"
#include "apcs/input/interactive_program.h"
#include "apcs/lesson/goal_check.h"
#include "apcs/lesson/replay_hooks.h"
#include "apcs/lesson/replay_rows.h"
#include "apcs/session/session.h"

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// On the caption row after q at a goal (SPEC §3.1): Y leaves the exercise (the replay ends, the
// keyboard is the student's), any other key goes back to the goal.
inline constexpr std::string_view leave_exercise_question = "Leave the exercise ? (Y/N)";

// On the caption row once a paced replay has played its script and the presenter asks for more.
inline constexpr std::string_view end_of_script_caption = "End of the script: the keyboard is yours (PgUp, Home: back)";
// In the badge after a key a paced replay does not take: the keys it does.
inline constexpr std::string_view replay_keys_on_space = "Space next step  PgDn next caption  Esc your keyboard";
inline constexpr std::string_view replay_keys_timed = "PgDn next caption  PgUp back  Esc your keyboard";
// In the badge once Esc (or a key typed after the end) gives the presenter the keyboard.
inline constexpr std::string_view replay_keys_keyboard = "your keyboard: PgUp/PgDn/Home return";
// Before a caption that closes a goal skipped by PgDn: it describes a goal that was not reached.
inline constexpr std::string_view skipped_caption_prefix = "(skipped) ";
// Before a caption that closes a goal judged not reached (a headless replay with no answer, a
// handout's page): the caption describes the goal, not the screen under it.
inline constexpr std::string_view not_reached_caption_prefix = "(not reached) ";

// What became of a goal of the script (SPEC §3.1): apcs.log has a line for each, apcs grade a row.
struct GoalOutcome {
    enum class Verdict { reached, not_reached, skipped };
    std::size_t goal = 0; // its index among the script's goals
    Verdict verdict = Verdict::not_reached;
    // As it was judged (SPEC §3.2): on its path as the student accepted it, else as it stood at the
    // next GOAL line or the end; how far it was when left with q or skipped.
    GoalProgress progress;
    std::size_t at_key = 0; // the keys the session had handled then
};

// Who watches a replay. On a terminal a person does: the script plays at its pace (ReplayPace),
// Esc hands the keyboard over, a goal waits for the student's keys until it holds (a goal that
// already holds is passed, its answer's keys skipped). Headless nobody does: the script plays at
// once and each goal's point is marked from its GOAL line to its answer's end. Either way a goal
// is judged on the path being shaped at its GOAL line (else the next one shaped), as the student
// accepted it - the moment the session leaves that path - or as it stands at the next GOAL line
// or the end (SPEC §3, §3.2): reaching it and moving away before the accept is not reaching it,
// and a value set on another path does not count.
enum class ReplayAudience { terminal, headless };

// A key script played into the session (SPEC §3, §3.1, §3.2): its steps, captions and goals, its
// pace and the step badge. The one replay of the program: the terminal drives it as any
// InteractiveProgram (keys in, screens out), the headless replay and apcs grade through
// play_to_idle. Every key the session handles passes through it, scripted or typed, and is kept
// (--record). A key typed on the terminal meets the replay in a state (state()) and does what the
// chart's row for that state and key says (replay_rows.h); the files beside this one keep the
// goals (replay_goals.cpp), the recording (replay_recording.cpp) and going back (replay_rewind.cpp).
class ReplayDriver final : public InteractiveProgram {
public:
    // `session` and `script` outlive the driver; `script_name` names the script in a goal's
    // FILE:LINE. On a terminal the captions and goals at the script's start are reached at once
    // (hooks told); headless, as the first key plays.
    ReplayDriver(Session& session, const KeyScript& script, std::string script_name, ReplayPace pace,
                 ReplayHooks hooks, ReplayAudience audience);

    // A key typed on the terminal: the row of the chart for the state it meets.
    void handle(const KeyEvent& key) override;
    void tick() override;
    // Headless: the session's work, else the script's next key once the session is idle.
    void work() override;
    bool finished() const override { return m_session->finished(); }
    bool animating() const override;
    bool busy() const override;
    int delay_ms() const override;
    // The session's screen with the caption reached (or the goal's feedback) and, when paced, the
    // step just played.
    ProgramScreen screen() const override;
    // The session's, advanced too when the caption or the badge changes: a key the replay swallows
    // leaves it.
    std::uint64_t screen_revision() const override { return m_session->screen_revision() + m_revision; }

    // Headless: whether the next work() is a script key known to leave the session's step where it
    // is (Session::keeps_step). False says nothing.
    bool next_work_keeps_step() const;

    // The state a key typed now meets (terminal).
    ReplayState state() const;
    // The action of the row the last key met; none before any key and after a written ignore. A
    // name_keys is forgotten once the script plays its next step (the badge names the step again).
    std::optional<ReplayAction> last_action() const { return m_last_action; }
    // What the chart's guards are tested against now.
    ReplayGuardFacts guard_facts() const;
    // Whether script keys are left to play and the lesson has the keyboard.
    bool playing() const;
    // The session the replay plays into: the one it was given until PgUp or Home replaced it.
    const Session& session() const { return *m_session; }
    // Headless: the captions left told and the goals left judged (the script's end). On a
    // terminal, once the session has ended (or a signal ended it): a goal not judged yet is judged
    // as it stands.
    void finish();
    // Headless: ok, or the first goal not reached, as "FILE:LINE: goal not reached: …".
    const Expected<void>& goals() const { return m_goals; }
    // Every key the session handled, in order.
    const std::vector<KeyEvent>& handled() const { return m_handled; }
    // The operations the session's keys and animation frames have cost so far (Session::key_work
    // of each, counted as it was handled): apcs grade's work budget.
    std::uint64_t work_done() const { return m_work_done; }
    // The same keys as --record writes them, with the script's INPUT, START, caption and GOAL
    // lines where the replay met them.
    KeyRecording recording() const;
    // Each goal judged so far, in order: headless every goal once finish() has run; on a terminal
    // the goals whose paths were accepted, those skipped or left, and the one open when the
    // session ended.
    const std::vector<GoalOutcome>& goal_outcomes() const { return m_outcomes; }
    // The KEY1 and KEY2 answers of every session the replay has played into, the one PgUp or Home
    // replaced too (a key file read there is still a file the program read), each once, sorted.
    std::vector<std::string> key_files_read() const;

private:
    // The replay's own part of the state; the rest is read off the session and the script's
    // position (state()).
    enum class Mode {
        deck,            // the script plays at its pace
        step_held,       // and a Space waits for the animation's end to be the next step
        at_goal,         // m_next_goal does not hold yet
        asking_to_leave, // q at that goal
        keyboard,        // the presenter's, until PgUp, PgDn or Home
        end_told,
        left, // the replay is over: the keyboard is the session's
    };
    // The words the replay lays over the session's screen.
    struct Overlay {
        std::string caption;
        std::string badge;
        std::string place; // "caption 2 of 7"
        bool operator==(const Overlay&) const = default;
    };
    // The words as the replay stands now.
    Overlay overlay_now() const;
    std::string place_in_badge(std::optional<std::size_t> caption) const;
    // The words as the replay stands laid, the revision advanced if they differ from those laid
    // before: the screen shows only words laid, so none change unseen by the terminal.
    void lay_overlay();
    void take(const KeyEvent& key);
    void act(ReplayAction action, const KeyEvent& key);
    void take_tick();
    void take_work();
    void play_headless();

    // replay_goals.cpp: where the replay stands with the session, captions told, goals met or
    // waited for.
    void settle();
    void after_change();
    // The captions the script has reached told, those before caption `limit` only.
    void tell_captions(std::size_t limit = static_cast<std::size_t>(-1));
    void end_caption();
    void wait_at_goal();
    // The goal m_next_goal checked again: its feedback on the message line. Whether it holds, or
    // its path was left before it did.
    enum class GoalCheck { holds, waits, path_left };
    GoalCheck check_waiting_goal();
    void pass_goal();
    void follow_passed_goal();
    void goal_path_left();
    // Where the session is with the open goal's path; bound to the path shaped if it had none.
    // Its standing is taken again when `look` (and the screen changed since).
    enum class GoalPath { not_shaped_yet, shaped, left };
    GoalPath follow_open_goal(bool look = true);
    GoalProgress open_goal_as_it_stands() const;
    void judge_open_goal(const GoalProgress& progress);
    std::size_t judging_end(std::size_t goal) const;
    // Headless: goals opened at their GOAL lines and judged, captions told between (see settle).
    void settle_headless(std::size_t played);
    void open_goal_headless();
    bool judge_goal_headless(std::size_t played);
    void say_goal_headless(std::string said);
    void judged(std::size_t goal, GoalOutcome::Verdict verdict, const GoalProgress& progress);
    void skip_goal();
    void leave_exercise();
    // The goal waited at (at_goal, asking_to_leave).
    std::optional<std::size_t> waiting_goal() const;
    // The verdict of the goal caption `caption` closes, if it closes one that PgDn skipped or that
    // a headless replay judged not reached; the caption as shown, prefixed accordingly.
    std::optional<GoalOutcome::Verdict> closed_goal_verdict(std::size_t caption) const;
    std::string caption_text(std::size_t caption) const;

    // replay_recording.cpp
    void to_session(const KeyEvent& key);
    // The script's lines a recording keeps (START, captions, GOAL), by the event they stand before.
    struct ScriptLine {
        std::size_t before_event = 0;
        enum class Kind { start, caption, goal } kind = Kind::start;
        std::size_t index = 0; // the caption's or the goal's
    };
    static std::vector<ScriptLine> script_lines(const KeyScript& script);
    // The script's START, captions and GOAL lines before event `event` into `recording`.
    void record_lines(KeyRecording& recording, std::size_t& lines_recorded, std::size_t event) const;

    // replay_rewind.cpp: PgUp, Home, and PgDn after Esc.
    void play_to_next_caption();
    void go_to_caption(std::size_t caption, std::string label);
    void rewind_to(std::size_t events, std::string label, std::size_t captions_shown);
    void catch_up(Session& session, std::size_t events);

    // The session neither splits nor shows the frames: a scripted key may play, a caption be reached.
    bool session_idle() const;
    // The replay's next key may play now on a terminal: the lesson has the keyboard, not at a
    // goal, the session idle. Headless, only play_headless plays a key.
    bool script_ready() const;
    // It plays without waiting for a key or the clock: at once, the rest of a step, a Space held
    // through the animation, the preamble or PgDn's run.
    bool plays_unasked() const;
    bool paced() const { return m_pace.kind != ReplayPace::Kind::at_once; }
    bool paced_every() const { return m_pace.kind == ReplayPace::Kind::every; }
    bool mid_step() const { return m_played < m_step_end; }
    bool lesson_has_keyboard() const { return m_mode == Mode::deck || m_mode == Mode::step_held; }
    void play_scripted();
    void stop();
    // The caption on the caption row (its index), none before the first.
    std::optional<std::size_t> caption_on_row() const;
    // The deck (SPEC §3.2): a paced replay shows each caption beside the screen its keys made. A
    // caption shows as its first key plays (Space), or at once with all its keys (PgDn); one
    // with no keys (a summary) by a press of its own.
    // Where caption `caption`'s keys end: the next caption's place, its goal's GOAL line, or the end.
    std::size_t caption_keys_end(std::size_t caption) const;
    // A goal stands where the script is, its task shown, not yet waited at (terminal).
    bool goal_due() const;
    // Paced: the next caption stands where the script is: the next step shows it.
    bool caption_due() const;
    // And it has no keys: the next step shows it alone.
    bool keyless_caption_due() const;
    void show_captions_through(std::size_t event);
    // Whether a goal may wait: paced, only once its task (the caption before its GOAL line) shows.
    bool task_shown(std::size_t goal) const;
    void go_to_start(std::string label);
    // Paced: whether a recording may hold `line` yet: a caption once shown, a GOAL line once its
    // task is (keys typed at caption K are not under caption K+1).
    bool line_met(const ScriptLine& line) const;

    Session* m_session;
    std::unique_ptr<Session> m_session_gone_back; // the session PgUp or Home made, if any
    std::set<std::string> m_key_files_of_sessions_replaced;
    const KeyScript& m_script;
    std::string m_script_name;
    ReplayPace m_pace;
    ReplayHooks m_hooks;
    ReplayAudience m_audience;
    Mode m_mode = Mode::deck;
    std::optional<ReplayAction> m_last_action;
    // The keys handled when the keyboard was handed over: the caption stays until one more is typed
    // (it would no longer be true of the screen).
    std::size_t m_handed_over_at = 0;
    std::size_t m_played = 0;
    std::size_t m_step_end = 0;
    std::size_t m_run_to = 0; // keys before it play unasked: the preamble, PgDn's run
    std::string m_step_label;
    std::size_t m_captions_shown = 0; // paced: the last one shown is on the row; 0 before the first
    std::size_t m_captions_told = 0;
    std::size_t m_captions_ended = 0;
    std::size_t m_next_goal = 0;
    std::size_t m_waiting_goal_line = 0; // its GOAL line among m_script_lines
    // A goal from its GOAL line until it is judged (SPEC §3.2; at most one at a time: the next GOAL
    // line judges it): its path, 0 or 1 (Session::shaped_path), once one is shaped, and how it
    // stood there when the replay last looked (the session's screen revision then).
    struct OpenGoal {
        std::size_t goal = 0;
        std::optional<int> path;
        GoalProgress standing;
        std::optional<std::uint64_t> looked_at;
    };
    std::optional<OpenGoal> m_open;
    // How far the goal waited at was at the last check, and the staff then (what the log says if
    // it is left; why a key that changed the staff did not move the in-between).
    GoalProgress m_waiting_progress;
    std::optional<StaffValues> m_waiting_staff;
    // Headless: the keys played when a goal's feedback or verdict went on the message line, which
    // keeps it until the next key (as the terminal keeps it at the goal).
    std::optional<std::size_t> m_goal_said_at;
    std::vector<GoalOutcome> m_outcomes;
    std::vector<ScriptLine> m_script_lines;
    KeyRecording m_recording;
    std::size_t m_lines_recorded = 0;
    Expected<void> m_goals = ok;
    std::vector<KeyEvent> m_handled;
    std::uint64_t m_work_done = 0;
    // Keys typed while the replay played unasked, taken once it has.
    std::deque<KeyEvent> m_typed_meanwhile;
    // The replay's own part of the screen revision: its words laid, and the sessions replaced.
    std::uint64_t m_revision = 0;
    Overlay m_laid;
};

} // namespace apcs
