#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/key_event.h"
#include "apcs/formats/key_recording.h"
#include "apcs/input/interactive_program.h"
#include "apcs/lesson/goal_check.h"
#include "apcs/lesson/replay_hooks.h"
#include "apcs/session/session.h"

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
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

// What became of a goal of the script (SPEC §3.1): apcs.log has a line for each, apcs grade a row.
struct GoalOutcome {
    enum class Verdict { reached, not_reached, skipped };
    std::size_t goal = 0; // its index among the script's goals
    Verdict verdict = Verdict::not_reached;
    GoalProgress progress; // when it was judged (reached, left, the session ended, the answer played)
    std::size_t at_key = 0; // the keys the session had handled then
};

// Who watches a replay. On a terminal a person does: the script plays at its pace (ReplayPace),
// Esc hands the keyboard over, a goal waits for the student's keys until it holds (a goal that
// already holds is passed, its answer's keys skipped). Headless nobody does: the script plays at
// once, each goal's point is marked from its GOAL line and the goal judged once its answer is
// played.
enum class ReplayAudience { terminal, headless };

// A key script played into the session (SPEC §3, §3.1): its steps, captions and goals, its pace
// and the step badge. The one replay of the program: the terminal drives it as any
// InteractiveProgram (keys in, screens out), the headless replay a step at a time (play_next).
// Every key the session handles passes through it, scripted or typed, and is kept (--record).
class ReplayDriver final : public InteractiveProgram {
public:
    // `session` and `script` outlive the driver; `script_name` names the script in a goal's
    // FILE:LINE. On a terminal the captions and goals at the script's start are reached at once
    // (hooks told); headless, with the first play_next.
    ReplayDriver(Session& session, const KeyScript& script, std::string script_name, ReplayPace pace,
                 ReplayHooks hooks, ReplayAudience audience);

    // A key typed on the terminal. While the replay waits for its pace, Space plays the next step
    // (on_space), Esc ends the replay and other keys are dropped; a Space typed while the
    // animation plays is the next step, held until it ends. At a goal, after the replay, or while
    // the session splits or animates, the key is the session's. Paced, the slide-deck keys are
    // the replay's (SPEC §3.1): PgDn (or ']') plays on to the next caption, or skips a goal;
    // PgUp (or '[') goes back to the previous caption's screen, Home to the first; at a goal and
    // at the script's end only PgDn, PgUp and Home, since '[' and ']' are the session's there.
    void handle(const KeyEvent& key) override;
    void tick() override;
    void work() override;
    bool finished() const override { return m_session->finished(); }
    bool animating() const override;
    bool busy() const override;
    int delay_ms() const override;
    // The session's screen with the caption reached (or the goal's feedback) and, when paced, the
    // step just played; neither once a key is typed after the replay.
    SessionScreen screen() const override;
    // The session's, advanced too when the caption or the badge changes: a key the replay swallows
    // leaves it.
    std::uint64_t screen_revision() const override { return m_session->screen_revision() + m_revision; }

    // Whether script keys are left to play (Esc has not ended the replay).
    bool playing() const { return !m_stopped && m_played < m_script.events.size(); }
    // The session the replay plays into: the one it was given until PgUp or Home replaced it.
    const Session& session() const { return *m_session; }
    // Headless: the captions and goals before the next key reached, then that key played.
    void play_next();
    // Headless: the captions left told and the goals left judged (the script's end).
    void finish();
    // Headless: ok, or the first goal not reached, as "FILE:LINE: goal not reached: …".
    const Expected<void>& goals() const { return m_goals; }
    // Every key the session handled, in order.
    const std::vector<KeyEvent>& handled() const { return m_handled; }
    // The same keys as --record writes them, with the script's INPUT, START, caption and GOAL
    // lines where the replay met them.
    KeyRecording recording() const;
    // Each goal judged so far, in order: headless every goal once finish() has run; on a terminal
    // the goals reached, skipped or left, and the one waited at when the session ended.
    const std::vector<GoalOutcome>& goal_outcomes() const { return m_outcomes; }

private:
    // What the replay lays over the session's screen.
    struct Shown {
        std::string caption;
        std::string badge;
        std::string place; // "caption 2 of 7"
        bool operator==(const Shown&) const = default;
    };
    Shown shown() const;
    // `change` done, the revision advanced if what the replay shows changed.
    template <typename Change>
    void watching(Change change);
    void take(const KeyEvent& key);
    void take_tick();
    void take_work();
    // Where the replay stands with the session: captions told, goals met or waited for.
    void settle();
    void after_change();
    void tell_captions();
    void end_caption();
    void wait_at_goal();
    // The goal waited at, checked again: its feedback on the message line, its answer skipped once
    // it holds. Whether it holds.
    bool check_waiting_goal();
    void judge_goals(std::size_t played);
    void judged(std::size_t goal, GoalOutcome::Verdict verdict, const GoalProgress& progress);
    // The script's START, captions and GOAL lines before event `event` into `recording`.
    void record_lines(KeyRecording& recording, std::size_t& lines_recorded, std::size_t event) const;
    // The session neither splits nor animates: a scripted key may play, a caption be reached.
    bool session_idle() const { return !m_session->busy() && !m_session->animating(); }
    // The replay's next key may play now on a terminal: not at a goal, nor while the session
    // works. Headless, only play_next plays a key.
    bool script_ready() const
    {
        return m_audience == ReplayAudience::terminal && !at_goal() && playing() && session_idle();
    }
    // A terminal replay waits at a goal that does not hold yet, its feedback on the caption row.
    bool at_goal() const { return !m_goal_said.empty(); }
    // It plays without waiting for a key or the clock: at once, the rest of a TEXT line, or a
    // Space held through the animation.
    bool plays_unasked() const;
    bool paced_every() const { return m_pace.kind == ReplayPace::Kind::every; }
    bool mid_step() const { return m_played < m_step_end; }
    void play_scripted();
    void to_session(const KeyEvent& key);
    // The script's lines a recording keeps (START, captions, GOAL), by the event they stand before.
    struct ScriptLine {
        std::size_t before_event = 0;
        enum class Kind { start, caption, goal } kind = Kind::start;
        std::size_t index = 0; // the caption's or the goal's
    };
    static std::vector<ScriptLine> script_lines(const KeyScript& script);
    void stop();
    void leave_exercise();
    // The slide-deck keys (SPEC §3.1).
    enum class Control { next, back, first };
    std::optional<Control> control_of(const KeyEvent& key) const;
    bool take_control(const KeyEvent& key);
    void play_to_next_caption();
    void skip_goal();
    void go_back_to(std::size_t caption, std::string label);
    void catch_up(Session& session, std::size_t events);
    // The caption on the caption row (its index), none before the first.
    std::optional<std::size_t> caption_on_row() const;
    bool paced() const { return m_pace.kind != ReplayPace::Kind::at_once; }
    bool at_end() const { return !m_stopped && m_played == m_script.events.size(); }

    Session* m_session;
    std::unique_ptr<Session> m_session_gone_back; // the session PgUp or Home made, if any
    const KeyScript& m_script;
    std::string m_script_name;
    ReplayPace m_pace;
    ReplayHooks m_hooks;
    ReplayAudience m_audience;
    std::size_t m_played = 0;
    std::size_t m_step_end = 0;
    std::size_t m_run_to = 0; // keys before it play unasked: the preamble, PgDn's run
    std::string m_step_label;
    bool m_end_told = false;
    bool m_controls_told = false; // a key the paced replay does not take: the badge names those it does
    std::size_t m_captions_told = 0;
    std::size_t m_captions_ended = 0;
    std::size_t m_next_goal = 0;
    std::string m_goal_said;
    // The goal waited at and how far it was at the last check (what the log says if it is left).
    std::optional<std::size_t> m_waiting_goal;
    std::size_t m_waiting_goal_line = 0; // its GOAL line among m_script_lines
    GoalProgress m_waiting_progress;
    std::optional<StaffValues> m_waiting_staff;
    bool m_reached_said = false; // "GOAL REACHED: …" stays until the next key
    std::vector<GoalOutcome> m_outcomes;
    std::vector<ScriptLine> m_script_lines;
    KeyRecording m_recording;
    std::size_t m_lines_recorded = 0;
    bool m_step_held = false;
    bool m_stopped = false;
    bool m_typed_after = false;
    bool m_leave_asked = false; // q at a goal: the next key answers leave_exercise_question
    Expected<void> m_goals = ok;
    std::vector<KeyEvent> m_handled;
    // Keys typed while the replay played unasked, the session's or the replay's once it stops.
    std::deque<KeyEvent> m_typed_meanwhile;
    std::uint64_t m_revision = 0;
};

} // namespace apcs
