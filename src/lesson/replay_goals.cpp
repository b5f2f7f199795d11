#include "apcs/lesson/replay_driver.h"

#include "apcs/lesson/goal_check.h"
#include "apcs/screens/replay_caption.h"

#include <algorithm>
#include <utility>

// Where the replay stands with the session: captions told and ended, goals met, waited for,
// skipped or left.
namespace apcs {

namespace {

// The goal as the student waiting at it sees it: its feedback on the message line, its point
// marked while it does not hold.
void show_standing(Session& session, const ScriptGoal& goal, const GoalProgress& progress)
{
    session.say_goal(goal_feedback(progress), goal_feedback_briefly(progress));
    session.mark_goal(progress.reached ? std::nullopt : goal_point(goal));
}

} // namespace

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
        settle_headless(m_played);
        return;
    }
    if (lesson_has_keyboard() && session_idle())
        tell_captions();
    wait_at_goal();
    // A session ended at a goal (quit): the goal was not reached, as far as it was then.
    if (m_session->finished() && waiting_goal() && m_open)
        goal_path_left();
    if (!playing() && session_idle() && !waiting_goal())
        end_caption();
    // A Space held through the script's last animation: the next step is the end.
    if (m_mode == Mode::step_held && !playing() && !caption_due() && session_idle())
        m_mode = paced() ? Mode::end_told : Mode::deck;
}

void ReplayDriver::tell_captions(std::size_t limit)
{
    const std::vector<ScriptCaption>& captions = m_script.captions;
    limit = std::min(limit, captions.size());
    for (; m_captions_told < limit && captions[m_captions_told].before_event <= m_played; ++m_captions_told) {
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
        m_hooks.caption_ended(m_captions_ended - 1, caption_text(m_captions_ended - 1), m_session->screen(),
                              key_files_read());
}

std::optional<std::size_t> ReplayDriver::waiting_goal() const
{
    if (m_mode == Mode::at_goal || m_mode == Mode::asking_to_leave)
        return m_next_goal;
    return std::nullopt;
}

// A goal that does not hold yet keeps the replay there, its feedback on the message line ("GOAL:
// tension +0.10, want …") under the task's caption and its point marked, while the student's keys
// go to the session; a goal that holds is passed ("GOAL REACHED: …" until the next key), its
// answer's keys skipped, and stays open until it is judged (follow_passed_goal). A goal whose path
// is accepted before it holds ends the exercise there (goal_path_left).
void ReplayDriver::wait_at_goal()
{
    if (!session_idle())
        return;
    follow_passed_goal();
    if (m_mode != Mode::at_goal && !lesson_has_keyboard())
        return;
    if (mid_step())
        return;
    if (m_mode == Mode::at_goal) {
        switch (check_waiting_goal()) {
        case GoalCheck::holds: pass_goal(); break;
        case GoalCheck::waits: return;
        case GoalCheck::path_left: goal_path_left(); return;
        }
    }
    const std::vector<ScriptGoal>& goals = m_script.goals;
    while (m_next_goal < goals.size() && goals[m_next_goal].before_event <= m_played && task_shown(m_next_goal)) {
        // The next GOAL line: a goal passed before it is judged as it stands (SPEC §3).
        if (m_open)
            judge_open_goal(open_goal_as_it_stands());
        if (goals[m_next_goal].before_event < m_played) {
            ++m_next_goal;
            continue;
        }
        m_open = OpenGoal{m_next_goal, std::nullopt, {}, std::nullopt};
        const GoalCheck check = check_waiting_goal();
        if (check == GoalCheck::holds) {
            pass_goal();
            continue;
        }
        m_mode = Mode::at_goal; // a goal is the student's: a Space held before it is not its answer
        m_waiting_goal_line = static_cast<std::size_t>(
            std::find_if(m_script_lines.begin(), m_script_lines.end(), [&](const ScriptLine& line) {
                return line.kind == ScriptLine::Kind::goal && line.index == m_next_goal;
            }) - m_script_lines.begin());
        if (check == GoalCheck::path_left)
            goal_path_left();
        return;
    }
}

ReplayDriver::GoalCheck ReplayDriver::check_waiting_goal()
{
    const ScriptGoal& goal = m_script.goals[m_next_goal];
    const GoalPath path = follow_open_goal();
    if (path == GoalPath::left)
        return GoalCheck::path_left;
    GoalProgress progress = open_goal_as_it_stands();
    const PathEditor* editor = m_session->path_editor();
    const std::optional<StaffValues> staff = editor ? editor->region_staff() : std::nullopt;
    // A key that changed the staff but left the in-between where it was: say why.
    if (m_mode == Mode::at_goal && !progress.reached && staff && m_waiting_staff && staff != m_waiting_staff &&
        progress.value == m_waiting_progress.value)
        explain_unmoved(progress, goal, *m_session);
    show_standing(*m_session, goal, progress);
    const bool holds = progress.reached;
    m_waiting_progress = std::move(progress);
    m_waiting_staff = staff;
    return holds ? GoalCheck::holds : GoalCheck::waits;
}

// The goal waited at holds: passed as today, its answer's keys skipped and the replay on at its
// pace; its verdict waits for its path to be accepted (follow_passed_goal).
void ReplayDriver::pass_goal()
{
    m_mode = Mode::deck;
    m_played = m_step_end = m_script.goals[m_next_goal++].answer_end;
    // A caption after the answer with no keys of its own (the one closing the goal) is about the
    // path as the student left it: it shows at once, beside it.
    if (keyless_caption_due())
        ++m_captions_shown;
}

// On a terminal, a goal passed (it held) until it is judged: when its path is left (accepted, or
// the session quit there) or the session ends, as the path was then; at the next GOAL line, as it
// stands there. A student who reaches the goal, moves away and accepts the path has not reached
// it.
void ReplayDriver::follow_passed_goal()
{
    if (!m_open || waiting_goal())
        return;
    const bool next_goal_line = m_open->goal + 1 < m_script.goals.size() && judging_end(m_open->goal) <= m_played;
    if (follow_open_goal() == GoalPath::left || m_session->finished() || next_goal_line)
        judge_open_goal(open_goal_as_it_stands());
}

// The goal waited at, its path left before the goal held: accepted (N at "Adjust the path again
// ?") or the session ended there. It is not reached, as the path was then, and the exercise is
// over: the keyboard is the student's in the session as it stands (as after q and Y), the message
// line saying so until the next key. Another path cannot reach it.
void ReplayDriver::goal_path_left()
{
    const GoalProgress standing = open_goal_as_it_stands();
    stop();
    m_mode = Mode::left;
    m_session->mark_goal(std::nullopt);
    m_session->say_goal(m_session->finished() ? std::string()
                                              : "GOAL not reached on the path accepted: " + standing.said_briefly +
                                                    ", " + standing.want);
    judge_open_goal(standing);
}

// The open goal's path (SPEC §3.2): the one shaped when the replay reached its GOAL line, else the
// next one shaped. Its standing is taken again while that path is shaped and its screen changed.
ReplayDriver::GoalPath ReplayDriver::follow_open_goal(bool look)
{
    OpenGoal& open = *m_open;
    const std::optional<int> shaped = m_session->shaped_path();
    if (!open.path)
        open.path = shaped;
    if (!open.path)
        return GoalPath::not_shaped_yet;
    if (shaped != open.path)
        return GoalPath::left;
    if (look && open.looked_at != m_session->screen_revision()) {
        open.standing = check_goal(m_script.goals[open.goal], *m_session);
        open.looked_at = m_session->screen_revision();
    }
    return GoalPath::shaped;
}

// On its path, as it stood there when last looked at (as accepted, once the path is left); before
// any path was shaped, as the session is ("no path is being shaped": not reached).
GoalProgress ReplayDriver::open_goal_as_it_stands() const
{
    if (m_open->path)
        return m_open->standing;
    return check_goal(m_script.goals[m_open->goal], *m_session);
}

// The open goal's verdict, `progress` as it was judged: reached or not. Headless, the first goal
// not reached is the run's failure.
void ReplayDriver::judge_open_goal(const GoalProgress& progress)
{
    const std::size_t index = m_open->goal;
    m_open.reset();
    const ScriptGoal& goal = m_script.goals[index];
    if (m_audience == ReplayAudience::headless && !progress.reached && m_goals)
        m_goals = Diagnostic{m_script_name, goal.line_number, "goal not reached: " + goal_distance_text(progress)};
    judged(index, progress.reached ? GoalOutcome::Verdict::reached : GoalOutcome::Verdict::not_reached, progress);
}

// The keys before a goal's verdict at the latest: the next GOAL line's, or the script's end.
std::size_t ReplayDriver::judging_end(std::size_t goal) const
{
    const std::vector<ScriptGoal>& goals = m_script.goals;
    return goal + 1 < goals.size() ? goals[goal + 1].before_event : m_script.events.size();
}

// Headless, with `played` keys played (the script's end when finishing), as a class would see it
// at each caption's end (SPEC §3.2: the handout's page K is the projector's screen at caption K):
// each goal opened at its GOAL line, its task's page showing its feedback ("GOAL: tension +0.00,
// want …") and its point marked while it does not hold, as the terminal waits there; judged on its
// path as the student accepted it (the session left the path), else as it stands at the next GOAL
// line or the script's end (SPEC §3, §3.2), its closing caption's page then saying "GOAL not
// reached: …" under "(not reached) …" when it was not. The first not reached is the run's failure.
// What the replay says stays on the message line until the next key; the point of the goal whose
// answer is playing is marked until its answer's end.
void ReplayDriver::settle_headless(std::size_t played)
{
    const std::vector<ScriptGoal>& goals = m_script.goals;
    if (m_goal_said_at && *m_goal_said_at < m_played)
        say_goal_headless({});
    // On while an answer plays, before a goal opened or judged here marks its point or clears it
    // and captions end over it.
    const bool answering = m_next_goal > 0 && goals[m_next_goal - 1].answer_end > played;
    m_session->mark_goal(answering ? goal_point(goals[m_next_goal - 1]) : std::nullopt);
    for (;;) {
        if (!m_open) {
            if (m_next_goal == goals.size() || goals[m_next_goal].before_event > played)
                break;
            open_goal_headless();
        }
        if (!judge_goal_headless(played))
            break;
    }
    tell_captions();
}

// Goal m_next_goal's GOAL line reached: its task and the captions before it told first, ending as
// they stood, then its feedback and mark as the terminal shows them waiting there.
void ReplayDriver::open_goal_headless()
{
    const ScriptGoal& goal = m_script.goals[m_next_goal];
    tell_captions(goal.captions_before);
    m_open = OpenGoal{m_next_goal++, std::nullopt, {}, std::nullopt};
    follow_open_goal();
    show_standing(*m_session, goal, open_goal_as_it_stands());
    m_goal_said_at = m_played; // until the next key
}

// The open goal judged if its path was left or its judging comes at `played`: the captions before
// the next goal's task told first (its own task's page shows its feedback), then the verdict. False
// while it stays open.
bool ReplayDriver::judge_goal_headless(std::size_t played)
{
    // A key that keeps its step cannot leave the goal's path: the standing is taken before a key
    // that may, and when judged, not before every key (a NEAR goal's look reads the whole curve,
    // and a recording may insert 16,000 waypoints).
    const bool judging = judging_end(m_open->goal) <= played;
    const bool look = judging || played >= m_script.events.size() || !m_session->keeps_step(m_script.events[played]);
    if (follow_open_goal(look) != GoalPath::left && !judging)
        return false;
    const std::vector<ScriptGoal>& goals = m_script.goals;
    const std::size_t next = m_open->goal + 1;
    if (next == goals.size())
        tell_captions();
    else if (goals[next].captions_before > 0)
        tell_captions(goals[next].captions_before - 1);
    // A task no caption follows before the next goal's (two goals, no answer): its page now, with
    // its feedback, not the verdict.
    if (m_captions_told > 0 && m_captions_told == goals[m_open->goal].captions_before)
        end_caption();
    const GoalProgress progress = open_goal_as_it_stands();
    judge_open_goal(progress);
    if (!progress.reached) {
        say_goal_headless(goal_verdict_line("not reached", progress));
        m_session->mark_goal(std::nullopt);
    }
    return true;
}

// Headless, what the replay says of a goal stays on the message line until the next key.
void ReplayDriver::say_goal_headless(std::string said)
{
    m_goal_said_at = said.empty() ? std::nullopt : std::optional<std::size_t>(m_played);
    m_session->say_goal(std::move(said));
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

// PgDn at a goal: passed as a goal that holds is, its answer's keys not played; the message line
// says how far it was (SPEC §3.2: nothing on screen may look as if it was reached), apcs.log
// "goal skipped".
void ReplayDriver::skip_goal()
{
    m_session->mark_goal(std::nullopt);
    m_session->say_goal(goal_verdict_line("skipped", m_waiting_progress));
    m_open.reset();
    judged(m_next_goal, GoalOutcome::Verdict::skipped, m_waiting_progress);
    m_mode = Mode::deck;
    m_played = m_step_end = m_script.goals[m_next_goal++].answer_end;
    m_step_label = "PGDN";
    // As any PgDn: the next caption (the goal's closing one, "(skipped) …") and its keys; a second
    // GOAL line under the same task waits first.
    if (!goal_due())
        play_to_next_caption();
}

// The verdict of the goal caption `caption` closes: a caption after the goal's GOAL line, reached
// by its answer's end, that is not the task of a later goal; only a goal skipped, or headless not
// reached.
std::optional<GoalOutcome::Verdict> ReplayDriver::closed_goal_verdict(std::size_t caption) const
{
    const std::vector<ScriptGoal>& goals = m_script.goals;
    const bool a_later_task = std::any_of(goals.begin(), goals.end(), [&](const ScriptGoal& goal) {
        return goal.captions_before == caption + 1;
    });
    if (a_later_task)
        return std::nullopt;
    // On a terminal a goal not reached leaves the replay (q and Y, its path accepted) or is judged
    // after its closing caption was shown beside the goal reached; PgUp replays its answer: only a
    // skip is said there.
    const auto said = [&](GoalOutcome::Verdict verdict) {
        return verdict == GoalOutcome::Verdict::skipped ||
               (verdict == GoalOutcome::Verdict::not_reached && m_audience == ReplayAudience::headless);
    };
    const auto closed = std::find_if(m_outcomes.begin(), m_outcomes.end(), [&](const GoalOutcome& outcome) {
        const ScriptGoal& goal = goals[outcome.goal];
        return said(outcome.verdict) && caption >= goal.captions_before &&
               m_script.captions[caption].before_event <= goal.answer_end;
    });
    return closed == m_outcomes.end() ? std::nullopt : std::optional(closed->verdict);
}

std::string ReplayDriver::caption_text(std::size_t caption) const
{
    const std::optional<GoalOutcome::Verdict> verdict = closed_goal_verdict(caption);
    std::string_view prefix;
    if (verdict)
        prefix = *verdict == GoalOutcome::Verdict::skipped ? skipped_caption_prefix : not_reached_caption_prefix;
    return std::string(prefix) + m_script.captions[caption].text;
}

// Y to "Leave the exercise ?": the replay ends there, its goal not reached, and the keyboard is
// the student's in the session as it stands.
void ReplayDriver::leave_exercise()
{
    const std::optional<std::size_t> goal = waiting_goal();
    stop();
    m_mode = Mode::left;
    m_session->mark_goal(std::nullopt);
    m_session->say_goal({});
    m_open.reset();
    if (goal)
        judged(*goal, GoalOutcome::Verdict::not_reached, m_waiting_progress);
}

} // namespace apcs
