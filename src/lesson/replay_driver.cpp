#include "apcs/lesson/replay_driver.h"

#include "apcs/lesson/goal_check.h"
#include "apcs/raster/replay_caption.h"

#include <algorithm>
#include <utility>

namespace apcs {

ReplayDriver::ReplayDriver(Session& session, const KeyScript& script, std::string script_name, ReplayPace pace,
                           ReplayHooks hooks, ReplayAudience audience)
    : m_session(&session)
    , m_script(script)
    , m_script_name(std::move(script_name))
    , m_pace(pace)
    , m_hooks(std::move(hooks))
    , m_audience(audience)
    , m_script_lines(script_lines(script))
{
    m_recording.add_inputs(script.inputs);
    // Headless, the captions and goals before the first key are reached with it (play_next).
    if (m_audience == ReplayAudience::terminal) {
        // The opening answers play as one step when a paced lesson begins: it starts where it teaches.
        if (paced())
            m_run_to = m_script.preamble_end;
        settle();
    }
}

bool ReplayDriver::plays_unasked() const
{
    return m_pace.kind == ReplayPace::Kind::at_once || mid_step() || m_step_held || m_played < m_run_to;
}

bool ReplayDriver::animating() const
{
    return m_session->animating() || (script_ready() && paced_every() && !plays_unasked());
}

bool ReplayDriver::busy() const
{
    return m_session->busy() || (script_ready() && plays_unasked()) || !m_typed_meanwhile.empty();
}

int ReplayDriver::delay_ms() const { return m_session->animating() ? m_session->delay_ms() : m_pace.milliseconds; }

template <typename Change>
void ReplayDriver::watching(Change change)
{
    const Shown before = shown();
    change();
    if (shown() != before)
        ++m_revision;
}

void ReplayDriver::handle(const KeyEvent& key)
{
    watching([&] { take(key); });
}

void ReplayDriver::tick()
{
    watching([&] { take_tick(); });
}

void ReplayDriver::work()
{
    watching([&] { take_work(); });
}

void ReplayDriver::take(const KeyEvent& key)
{
    if (std::exchange(m_reached_said, false))
        m_session->say_goal({});
    m_controls_told = false;
    if (script_ready() && plays_unasked()) {
        // Read once the keys that play unasked have played, as if typed then.
        m_typed_meanwhile.push_back(key);
        return;
    }
    if (!m_leave_asked && take_control(key)) {
        after_change();
        return;
    }
    if (script_ready()) {
        if (key.key == Key::escape)
            stop();
        else if (m_pace.kind == ReplayPace::Kind::on_space && key.key == Key::space)
            play_scripted();
        else
            // A key the replay does not take (8 at the 8/2 choice, say): the badge says which it does.
            m_controls_told = paced();
        after_change();
        return;
    }
    // Space after the script's last step: the end is told, the keyboard still the presenter's.
    if (paced() && at_end() && !at_goal() && !m_end_told && !m_typed_after && key.key == Key::space) {
        m_end_told = true;
        return;
    }
    // Paced a step per Space, a Space typed while the animation plays is the replay's next step,
    // held until the animation ends (not the animation's pause key, which would stop the lesson).
    if (!at_goal() && key.key == Key::space && m_pace.kind == ReplayPace::Kind::on_space && playing() &&
        m_session->animating()) {
        m_step_held = true;
        return;
    }
    if (m_leave_asked) {
        m_leave_asked = false;
        if (key == KeyEvent::typed(U'y') || key == KeyEvent::typed(U'Y'))
            leave_exercise();
        after_change();
        return;
    }
    // At a goal the keys are the student's, but q asks whether to leave it (a goal the student
    // cannot reach must not trap the class); where text is typed (a prompt, a staff value) q is a
    // letter of it.
    if (at_goal() && (key == KeyEvent::typed(U'q') || key == KeyEvent::typed(U'Q')) && !m_session->takes_typed_text()) {
        m_leave_asked = true;
        return;
    }
    if (!at_goal())
        m_typed_after = !playing();
    to_session(key);
    after_change();
}

// Y to "Leave the exercise ?": the replay ends there, its goal not reached, and the keyboard is
// the student's in the session as it stands.
void ReplayDriver::leave_exercise()
{
    stop();
    m_typed_after = true;
    m_session->mark_goal(std::nullopt);
    m_session->say_goal({});
    if (m_waiting_goal)
        judged(*std::exchange(m_waiting_goal, std::nullopt), GoalOutcome::Verdict::not_reached, m_waiting_progress);
}

void ReplayDriver::take_tick()
{
    if (m_session->animating())
        m_session->tick();
    else if (script_ready() && paced_every())
        play_scripted();
    after_change();
}

void ReplayDriver::take_work()
{
    if (m_session->busy()) {
        m_session->work();
    } else if (script_ready() && plays_unasked()) {
        // A held Space is taken by the step it plays.
        if (m_pace.kind != ReplayPace::Kind::at_once && !mid_step())
            m_step_held = false;
        play_scripted();
    } else if (!m_typed_meanwhile.empty()) {
        const KeyEvent key = m_typed_meanwhile.front();
        m_typed_meanwhile.pop_front();
        take(key);
        return;
    }
    after_change();
}

SessionScreen ReplayDriver::screen() const
{
    SessionScreen screen = m_session->screen();
    // The help fills the screen from its title to "Any key closes this help.": a caption there
    // would push the title off, the badge cover its first key line. Both come back as it closes.
    if (m_session->showing_help())
        return screen;
    Shown over = shown();
    screen.caption = std::move(over.caption);
    screen.badge = std::move(over.badge);
    screen.badge_place = std::move(over.place);
    return screen;
}

ReplayDriver::Shown ReplayDriver::shown() const
{
    if (m_leave_asked)
        return {std::string(leave_exercise_question), {}, {}};
    if (m_typed_after)
        return {};
    Shown over;
    const std::optional<std::size_t> caption = caption_on_row();
    if (caption)
        over.caption = m_script.captions[*caption].text;
    if (m_end_told && at_end() && !at_goal())
        over.caption = end_of_script_caption;
    if (!paced())
        return over;
    over.badge = m_step_label;
    if (m_controls_told) {
        over.place = m_pace.kind == ReplayPace::Kind::on_space ? replay_keys_on_space : replay_keys_timed;
        // The badge with the keys fits the 80-column top edge: a long step label gives way.
        constexpr std::size_t label_room = 12;
        if (over.badge.size() > label_room) {
            std::size_t cut = label_room - 3;
            while (cut > 0 && (static_cast<unsigned char>(over.badge[cut]) & 0xC0) == 0x80)
                --cut; // not inside a character
            over.badge = over.badge.substr(0, cut) + "...";
        }
    }
    else if (caption)
        over.place = "caption " + std::to_string(*caption + 1) + " of " + std::to_string(m_script.captions.size());
    return over;
}

void ReplayDriver::play_next()
{
    settle();
    play_scripted();
}

void ReplayDriver::finish()
{
    settle();
    judge_goals(m_script.events.size());
    end_caption();
}

// On a terminal the replay settles after everything the session does; headless, before each key
// (the moment the headless transcript has always printed a caption).
void ReplayDriver::after_change()
{
    if (m_audience == ReplayAudience::terminal)
        settle();
}

void ReplayDriver::settle()
{
    if (m_audience == ReplayAudience::headless) {
        judge_goals(m_played);
        tell_captions();
        return;
    }
    if (!m_stopped && session_idle())
        tell_captions();
    wait_at_goal();
    // A session ended at a goal (q, Y): the goal was not reached, as far as it was then.
    if (m_session->finished() && m_waiting_goal)
        judged(*std::exchange(m_waiting_goal, std::nullopt), GoalOutcome::Verdict::not_reached, m_waiting_progress);
    if (!playing() && session_idle() && !at_goal())
        end_caption();
    // A goal is the student's: a Space held before it is not its answer.
    if (at_goal())
        m_step_held = false;
}

void ReplayDriver::tell_captions()
{
    const std::vector<ScriptCaption>& captions = m_script.captions;
    for (; m_captions_told < captions.size() && captions[m_captions_told].before_event <= m_played; ++m_captions_told) {
        end_caption();
        if (m_hooks.caption_reached)
            m_hooks.caption_reached(m_captions_told, with_caption(m_session->screen(), captions[m_captions_told].text));
    }
}

// The caption told last has played its keys: the screen now is the one it is about.
void ReplayDriver::end_caption()
{
    if (m_captions_ended == m_captions_told)
        return;
    m_captions_ended = m_captions_told;
    if (m_hooks.caption_ended)
        m_hooks.caption_ended(m_captions_ended - 1, m_session->screen());
}

// A goal that does not hold yet keeps the replay there, its feedback on the message line ("GOAL:
// tension +0.10, want …") under the task's caption and its point marked, while the student's keys
// go to the session; a goal that holds is passed ("GOAL REACHED: …" until the next key), its
// answer's keys skipped.
void ReplayDriver::wait_at_goal()
{
    m_goal_said.clear();
    if (m_stopped || mid_step() || !session_idle())
        return;
    const std::vector<ScriptGoal>& goals = m_script.goals;
    for (; m_next_goal < goals.size() && goals[m_next_goal].before_event <= m_played; ++m_next_goal) {
        if (goals[m_next_goal].before_event < m_played)
            continue;
        if (!check_waiting_goal()) {
            m_waiting_goal_line = static_cast<std::size_t>(
                std::find_if(m_script_lines.begin(), m_script_lines.end(), [&](const ScriptLine& line) {
                    return line.kind == ScriptLine::Kind::goal && line.index == m_next_goal;
                }) - m_script_lines.begin());
            return;
        }
        m_played = m_step_end = goals[m_next_goal].answer_end;
    }
}

bool ReplayDriver::check_waiting_goal()
{
    const ScriptGoal& goal = m_script.goals[m_next_goal];
    GoalProgress progress = check_goal(goal, *m_session);
    const PathEditor* editor = m_session->path_editor();
    const std::optional<StaffValues> staff = editor ? editor->region_staff() : std::nullopt;
    // A key that changed the staff but left the in-between where it was: say why.
    if (m_waiting_goal == m_next_goal && !progress.reached && staff && m_waiting_staff && staff != m_waiting_staff &&
        progress.value == m_waiting_progress.value)
        explain_unmoved(progress, goal, *m_session);
    m_session->say_goal(goal_feedback(progress), goal_feedback_briefly(progress));
    m_session->mark_goal(progress.reached ? std::nullopt : goal_point(goal));
    if (progress.reached) {
        m_waiting_goal.reset();
        m_reached_said = true;
        judged(m_next_goal, GoalOutcome::Verdict::reached, progress);
        return true;
    }
    m_waiting_goal = m_next_goal;
    m_waiting_progress = std::move(progress);
    m_waiting_staff = staff;
    m_goal_said = goal_feedback(m_waiting_progress);
    return false;
}

// Headless: each goal judged once `played` keys have played its answer (the first not reached is
// the run's failure); the next goal's point marked from its GOAL line until then.
void ReplayDriver::judge_goals(std::size_t played)
{
    const std::vector<ScriptGoal>& goals = m_script.goals;
    for (; m_next_goal < goals.size() && goals[m_next_goal].answer_end <= played; ++m_next_goal) {
        const ScriptGoal& goal = goals[m_next_goal];
        const GoalProgress progress = check_goal(goal, *m_session);
        if (!progress.reached && m_goals)
            m_goals = Diagnostic{m_script_name, goal.line_number, "goal not reached: " + goal_distance_text(progress)};
        m_session->mark_goal(std::nullopt);
        judged(m_next_goal, progress.reached ? GoalOutcome::Verdict::reached : GoalOutcome::Verdict::not_reached,
               progress);
    }
    if (m_next_goal < goals.size() && goals[m_next_goal].before_event <= played)
        m_session->mark_goal(goal_point(goals[m_next_goal]));
}

// apcs.log's line for the goal: "goal reached: tension +0.45 at key 12", "goal not reached: tension
// +0.10, want +0.40 to +0.60", "goal skipped".
void ReplayDriver::judged(std::size_t goal, GoalOutcome::Verdict verdict, const GoalProgress& progress)
{
    m_outcomes.push_back({goal, verdict, progress, m_handled.size()});
    if (!m_hooks.log)
        return;
    switch (verdict) {
    case GoalOutcome::Verdict::reached:
        m_hooks.log("goal reached: " + progress.said + " at key " + std::to_string(m_handled.size()));
        break;
    case GoalOutcome::Verdict::not_reached: m_hooks.log("goal not reached: " + goal_distance_text(progress)); break;
    case GoalOutcome::Verdict::skipped: m_hooks.log("goal skipped"); break;
    }
}

void ReplayDriver::play_scripted()
{
    m_controls_told = false; // the badge names the step again
    if (!mid_step()) {
        m_step_end = m_played + step_length(m_script, m_played);
        m_step_label = step_label(m_script, m_played);
        // A run past the preamble is PgDn's (the preamble's own step is named START).
        if (m_played < m_run_to && m_played >= m_script.preamble_end)
            m_step_label = "PGDN";
    }
    // The key is recorded after the lines before it: m_played moves on once it is played.
    to_session(m_script.events[m_played]);
    ++m_played;
}

void ReplayDriver::to_session(const KeyEvent& key)
{
    record_lines(m_recording, m_lines_recorded, m_played);
    m_recording.add_key(key, m_session->takes_typed_text());
    m_handled.push_back(key);
    m_session->handle(key);
}

std::vector<ReplayDriver::ScriptLine> ReplayDriver::script_lines(const KeyScript& script)
{
    std::vector<ScriptLine> lines;
    if (script.preamble_end > 0)
        lines.push_back({script.preamble_end, ScriptLine::Kind::start, 0});
    for (std::size_t caption = 0; caption < script.captions.size(); ++caption)
        lines.push_back({script.captions[caption].before_event, ScriptLine::Kind::caption, caption});
    for (std::size_t goal = 0; goal < script.goals.size(); ++goal)
        lines.push_back({script.goals[goal].before_event, ScriptLine::Kind::goal, goal});
    // At one key, in the script's order: START first, then captions and GOAL lines as the goals'
    // captions_before place them (caption i before goal g when i < captions_before).
    const auto rank = [&script](const ScriptLine& line) -> std::size_t {
        switch (line.kind) {
        case ScriptLine::Kind::start: return 0;
        case ScriptLine::Kind::caption: return 2 * line.index + 1;
        case ScriptLine::Kind::goal: return 2 * script.goals[line.index].captions_before;
        }
        return 0;
    };
    std::stable_sort(lines.begin(), lines.end(), [&rank](const ScriptLine& a, const ScriptLine& b) {
        return a.before_event < b.before_event || (a.before_event == b.before_event && rank(a) < rank(b));
    });
    return lines;
}

void ReplayDriver::record_lines(KeyRecording& recording, std::size_t& lines_recorded, std::size_t event) const
{
    for (; lines_recorded < m_script_lines.size() && m_script_lines[lines_recorded].before_event <= event;
         ++lines_recorded) {
        const ScriptLine& line = m_script_lines[lines_recorded];
        // The student's keys at a goal come before the lines after its GOAL line (a closing caption).
        if (m_waiting_goal && line.before_event == event && line.kind != ScriptLine::Kind::start &&
            lines_recorded > m_waiting_goal_line)
            return;
        switch (line.kind) {
        case ScriptLine::Kind::start: recording.add_start(); break;
        case ScriptLine::Kind::caption: recording.add_caption(m_script.captions[line.index].text); break;
        case ScriptLine::Kind::goal: recording.add_goal(m_script.goals[line.index]); break;
        }
    }
}

KeyRecording ReplayDriver::recording() const
{
    KeyRecording recording = m_recording;
    std::size_t lines_recorded = m_lines_recorded;
    record_lines(recording, lines_recorded, m_played);
    return recording;
}

// Esc during a paced replay: the keyboard takes over, the caption on the row stays.
void ReplayDriver::stop()
{
    m_step_end = m_run_to = m_played;
    m_stopped = true;
}

std::optional<std::size_t> ReplayDriver::caption_on_row() const
{
    // A goal waiting shows its task, the caption before its GOAL line, not one that closes it.
    if (m_waiting_goal) {
        const std::size_t before = m_script.goals[*m_waiting_goal].captions_before;
        return before > 0 ? std::optional<std::size_t>(before - 1) : std::nullopt;
    }
    const ScriptCaption* caption = caption_at(m_script, m_played);
    if (caption == nullptr)
        return std::nullopt;
    return static_cast<std::size_t>(caption - m_script.captions.data());
}

std::optional<ReplayDriver::Control> ReplayDriver::control_of(const KeyEvent& key) const
{
    // '[' and ']' are the waypoint editor's where the session has the keyboard: at a goal, at the end.
    const bool brackets = script_ready();
    if (key.key == Key::page_down || (brackets && key == KeyEvent::typed(U']')))
        return Control::next;
    if (key.key == Key::page_up || (brackets && key == KeyEvent::typed(U'[')))
        return Control::back;
    if (key.key == Key::home)
        return Control::first;
    return std::nullopt;
}

// A slide-deck key, if `key` is one and the replay is the presenter's: paced, neither stopped by
// Esc nor followed by a key the student typed. Whether the key was taken.
bool ReplayDriver::take_control(const KeyEvent& key)
{
    const std::optional<Control> control = control_of(key);
    if (!control || !paced() || m_stopped || m_typed_after)
        return false;
    const std::optional<std::size_t> caption = caption_on_row();
    switch (*control) {
    case Control::next:
        if (at_goal())
            skip_goal();
        else if (playing())
            play_to_next_caption();
        else
            m_end_told = true;
        return true;
    case Control::back:
        go_back_to(caption && *caption > 0 ? *caption - 1 : 0, "PGUP");
        return true;
    case Control::first:
        go_back_to(0, "HOME");
        return true;
    }
    return false;
}

// The rest of the caption's keys play unasked; the next caption stops them (or a goal, or the end).
void ReplayDriver::play_to_next_caption()
{
    const std::vector<ScriptCaption>& captions = m_script.captions;
    const auto next = std::find_if(captions.begin(), captions.end(),
                                   [&](const ScriptCaption& caption) { return caption.before_event > m_played; });
    m_run_to = next == captions.end() ? m_script.events.size() : next->before_event;
    m_step_held = false;
}

// PgDn at a goal: passed as a goal that holds is, its answer's keys not played; apcs.log says so.
void ReplayDriver::skip_goal()
{
    m_session->mark_goal(std::nullopt);
    m_session->say_goal({});
    m_waiting_goal.reset();
    judged(m_next_goal, GoalOutcome::Verdict::skipped, m_waiting_progress);
    m_played = m_step_end = m_script.goals[m_next_goal++].answer_end;
    m_goal_said.clear();
    m_step_label = "PGDN";
}

// PgUp, Home: a new session on the inputs as they were when the replay started, the keys before
// caption `caption` played into it at once (writing nothing), and the replay on from there.
void ReplayDriver::go_back_to(std::size_t caption, std::string label)
{
    if (!m_hooks.session_as_started)
        return;
    const std::size_t events =
        m_script.captions.empty() ? m_script.preamble_end : m_script.captions[std::min(caption, m_script.captions.size() - 1)].before_event;
    std::unique_ptr<Session> session = m_hooks.session_as_started();
    m_recording = KeyRecording();
    m_recording.add_inputs(m_script.inputs);
    m_lines_recorded = 0;
    catch_up(*session, events);
    record_lines(m_recording, m_lines_recorded, events);
    if (m_hooks.caught_up)
        m_hooks.caught_up();
    // The new session counts its screens from 0: the sum the terminal watches must still grow.
    m_revision += m_session->screen_revision() + 1;
    m_session_gone_back = std::move(session);
    m_session = m_session_gone_back.get();
    m_handled.assign(m_script.events.begin(), m_script.events.begin() + static_cast<std::ptrdiff_t>(events));
    m_played = m_step_end = m_run_to = events;
    const std::vector<ScriptGoal>& goals = m_script.goals;
    m_next_goal = static_cast<std::size_t>(std::find_if(goals.begin(), goals.end(), [&](const ScriptGoal& goal) {
                                               return goal.before_event >= events;
                                           }) - goals.begin());
    m_goal_said.clear();
    m_waiting_goal.reset();
    std::erase_if(m_outcomes, [&](const GoalOutcome& outcome) { return outcome.goal >= m_next_goal; });
    m_step_held = m_end_told = m_leave_asked = m_reached_said = false;
    m_typed_meanwhile.clear();
    m_step_label = std::move(label);
}

// The first `events` keys of the script into `session`, each played to its end: the split, the
// picture's refinement and the animation run through, as the headless replay plays them.
void ReplayDriver::catch_up(Session& session, std::size_t events)
{
    for (std::size_t event = 0; event < events && !session.finished(); ++event) {
        record_lines(m_recording, m_lines_recorded, event);
        m_recording.add_key(m_script.events[event], session.takes_typed_text());
        session.handle(m_script.events[event]);
        while (session.busy() || session.animating())
            session.busy() ? session.work() : session.tick();
    }
}

} // namespace apcs
