#include "apcs/lesson/replay_driver.h"

#include "apcs/input/play_to_idle.h"

#include <algorithm>
#include <utility>

// The deck's moves (SPEC §3.1, §3.2): PgDn's run to the next caption, and going to a caption's
// screen replayed in memory from the inputs as they were when the replay started.
namespace apcs {

// PgDn (SPEC §3.2): the next caption shows and its keys play unasked (the rest of the one on the
// row first); the caption after it stops them (or a goal, or the end). Past the last caption, the
// script's rest.
void ReplayDriver::play_to_next_caption()
{
    if (paced() && m_captions_shown < m_script.captions.size())
        m_run_to = caption_keys_end(m_captions_shown++);
    else
        m_run_to = m_script.events.size();
    if (m_mode == Mode::step_held)
        m_mode = Mode::deck;
    m_step_label = "PGDN";
}

// Caption `caption` beside the screen its keys made; past the last caption, the script's end.
void ReplayDriver::go_to_caption(std::size_t caption, std::string label)
{
    const std::vector<ScriptCaption>& captions = m_script.captions;
    if (captions.empty()) {
        rewind_to(m_script.preamble_end, std::move(label), 0);
        return;
    }
    caption = std::min(caption, captions.size() - 1);
    rewind_to(caption_keys_end(caption), std::move(label), caption + 1);
}

// The lesson's first screen: its opening answers played, no caption shown yet.
void ReplayDriver::go_to_start(std::string label) { rewind_to(m_script.preamble_end, std::move(label), 0); }

// A new session on the inputs as they were when the replay started, the first `events` keys played
// into it at once (writing nothing), and the lesson on from there with the keyboard.
void ReplayDriver::rewind_to(std::size_t events, std::string label, std::size_t captions_shown)
{
    if (!m_hooks.session_as_started)
        return;
    // Told before the catch-up, whose recording holds the captions shown.
    m_captions_shown = captions_shown;
    std::unique_ptr<Session> session = m_hooks.session_as_started();
    m_recording = KeyRecording();
    m_recording.add_inputs(m_script.inputs);
    m_lines_recorded = 0;
    // The lines at `events` itself (the next caption, a GOAL line) are the replay's to record as it
    // meets them: a goal's answer comes after its GOAL line, before the caption that closes it.
    catch_up(*session, events);
    if (m_hooks.caught_up)
        m_hooks.caught_up();
    // The new session counts its screens from 0: the sum the terminal watches must still grow.
    m_revision += m_session->screen_revision() + 1;
    for (const std::string& key : m_session->key_names())
        if (!key.empty())
            m_key_files_of_sessions_replaced.insert(key);
    m_session_gone_back = std::move(session);
    m_session = m_session_gone_back.get();
    m_handled.assign(m_script.events.begin(), m_script.events.begin() + static_cast<std::ptrdiff_t>(events));
    m_played = m_step_end = m_run_to = events;
    const std::vector<ScriptGoal>& goals = m_script.goals;
    m_next_goal = static_cast<std::size_t>(std::find_if(goals.begin(), goals.end(), [&](const ScriptGoal& goal) {
                                               return goal.before_event >= events;
                                           }) - goals.begin());
    std::erase_if(m_outcomes, [&](const GoalOutcome& outcome) { return outcome.goal >= m_next_goal; });
    // A goal passed before the caption gone back to stays open, on the new session's path.
    if (m_open && m_open->goal >= m_next_goal)
        m_open.reset();
    else if (m_open)
        m_open->looked_at.reset();
    m_mode = Mode::deck;
    m_session->say_goal({});
    m_typed_meanwhile.clear();
    m_step_label = std::move(label);
}

std::vector<std::string> ReplayDriver::key_files_read() const
{
    std::set<std::string> read = m_key_files_of_sessions_replaced;
    for (const std::string& key : m_session->key_names())
        if (!key.empty())
            read.insert(key);
    return {read.begin(), read.end()};
}

// The first `events` keys of the script into `session`, each played to its end: the split, the
// picture's refinement and the animation run through, as the headless replay plays them.
void ReplayDriver::catch_up(Session& session, std::size_t events)
{
    for (std::size_t event = 0; event < events && !session.finished(); ++event) {
        record_lines(m_recording, m_lines_recorded, event);
        m_recording.add_key(m_script.events[event], session.takes_typed_text());
        session.handle(m_script.events[event]);
        play_to_idle(session);
    }
}

} // namespace apcs
