#include "apcs/lesson/replay_driver.h"

#include "apcs/lesson/goal_check.h"
#include "apcs/raster/replay_caption.h"

#include <algorithm>
#include <utility>

// Where the replay stands with the session: captions told and ended, goals met, waited for,
// skipped or left.
namespace apcs {

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
    if (lesson_has_keyboard() && session_idle())
        tell_captions();
    wait_at_goal();
    // A session ended at a goal (quit): the goal was not reached, as far as it was then.
    if (m_session->finished() && waiting_goal()) {
        judged(m_next_goal, GoalOutcome::Verdict::not_reached, m_waiting_progress);
        m_mode = Mode::left;
    }
    if (!playing() && session_idle() && !waiting_goal())
        end_caption();
    // A Space held through the script's last animation: the next step is the end.
    if (m_mode == Mode::step_held && !playing() && session_idle())
        m_mode = paced() ? Mode::end_told : Mode::deck;
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
        m_hooks.caption_ended(m_captions_ended - 1, m_session->screen(), key_files_read());
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
// answer's keys skipped.
void ReplayDriver::wait_at_goal()
{
    if (m_mode != Mode::at_goal && !lesson_has_keyboard())
        return;
    if (mid_step() || !session_idle())
        return;
    const std::vector<ScriptGoal>& goals = m_script.goals;
    for (; m_next_goal < goals.size() && goals[m_next_goal].before_event <= m_played; ++m_next_goal) {
        if (goals[m_next_goal].before_event < m_played)
            continue;
        if (!check_waiting_goal()) {
            m_mode = Mode::at_goal; // a goal is the student's: a Space held before it is not its answer
            m_waiting_goal_line = static_cast<std::size_t>(
                std::find_if(m_script_lines.begin(), m_script_lines.end(), [&](const ScriptLine& line) {
                    return line.kind == ScriptLine::Kind::goal && line.index == m_next_goal;
                }) - m_script_lines.begin());
            return;
        }
        m_mode = Mode::deck;
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
    if (m_mode == Mode::at_goal && !progress.reached && staff && m_waiting_staff && staff != m_waiting_staff &&
        progress.value == m_waiting_progress.value)
        explain_unmoved(progress, goal, *m_session);
    m_session->say_goal(goal_feedback(progress), goal_feedback_briefly(progress));
    m_session->mark_goal(progress.reached ? std::nullopt : goal_point(goal));
    if (progress.reached) {
        judged(m_next_goal, GoalOutcome::Verdict::reached, progress);
        return true;
    }
    m_waiting_progress = std::move(progress);
    m_waiting_staff = staff;
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

// PgDn at a goal: passed as a goal that holds is, its answer's keys not played; the message line
// says how far it was (SPEC §3.2: nothing on screen may look as if it was reached), apcs.log
// "goal skipped".
void ReplayDriver::skip_goal()
{
    m_session->mark_goal(std::nullopt);
    m_session->say_goal("GOAL skipped: " + goal_distance_text(m_waiting_progress));
    judged(m_next_goal, GoalOutcome::Verdict::skipped, m_waiting_progress);
    m_mode = Mode::deck;
    m_played = m_step_end = m_script.goals[m_next_goal++].answer_end;
    m_step_label = "PGDN";
}

// A caption after the goal's GOAL line, reached by its answer's end, that is not the task of a
// later goal.
bool ReplayDriver::closes_skipped_goal(std::size_t caption) const
{
    const std::vector<ScriptGoal>& goals = m_script.goals;
    const bool a_later_task = std::any_of(goals.begin(), goals.end(), [&](const ScriptGoal& goal) {
        return goal.captions_before == caption + 1;
    });
    return !a_later_task && std::any_of(m_outcomes.begin(), m_outcomes.end(), [&](const GoalOutcome& outcome) {
        const ScriptGoal& goal = goals[outcome.goal];
        return outcome.verdict == GoalOutcome::Verdict::skipped && caption >= goal.captions_before &&
               m_script.captions[caption].before_event <= goal.answer_end;
    });
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
    if (goal)
        judged(*goal, GoalOutcome::Verdict::not_reached, m_waiting_progress);
}

} // namespace apcs
