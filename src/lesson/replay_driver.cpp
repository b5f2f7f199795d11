#include "apcs/lesson/replay_driver.h"


#include <algorithm>
#include <utility>

// The replay's policy: which state a key meets, and what the chart's row for it does.
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
    // Headless, the captions and goals before the first key are reached with it.
    if (m_audience == ReplayAudience::terminal) {
        // The opening answers play as one step when a paced lesson begins: it starts where it teaches.
        if (paced())
            m_run_to = m_script.preamble_end;
        settle();
    }
    m_laid = overlay_now();
}

ReplayState ReplayDriver::state() const
{
    switch (m_mode) {
    case Mode::at_goal: return ReplayState::at_goal;
    case Mode::asking_to_leave: return ReplayState::asking_to_leave;
    case Mode::keyboard: return ReplayState::keyboard;
    case Mode::end_told: return ReplayState::end_told;
    case Mode::left: return ReplayState::left;
    case Mode::deck:
    case Mode::step_held: break;
    }
    if (m_session->showing_frames()) {
        if (!m_session->animating())
            return ReplayState::animation_paused;
        return m_mode == Mode::step_held ? ReplayState::animation_step_held : ReplayState::animation_playing;
    }
    if (m_session->working())
        return ReplayState::session_working;
    if (m_played == m_script.events.size() && !caption_due())
        return ReplayState::end;
    if (plays_unasked())
        return ReplayState::playing_unasked;
    return m_pace.kind == ReplayPace::Kind::on_space ? ReplayState::waiting_for_space : ReplayState::waiting_for_clock;
}

bool ReplayDriver::playing() const
{
    return m_mode != Mode::keyboard && m_mode != Mode::left && m_played < m_script.events.size();
}

bool ReplayDriver::session_idle() const
{
    return !m_session->working() && !m_session->animating() && !m_session->showing_frames();
}

bool ReplayDriver::script_ready() const
{
    return m_audience == ReplayAudience::terminal && lesson_has_keyboard() && (playing() || caption_due()) &&
           session_idle();
}

bool ReplayDriver::plays_unasked() const
{
    return m_pace.kind == ReplayPace::Kind::at_once || mid_step() || m_mode == Mode::step_held ||
           m_played < m_run_to;
}

bool ReplayDriver::animating() const
{
    return m_session->animating() || (script_ready() && paced_every() && !plays_unasked());
}

bool ReplayDriver::busy() const
{
    if (m_audience == ReplayAudience::headless)
        return m_session->busy() || (playing() && !m_session->animating());
    return m_session->busy() || (script_ready() && plays_unasked()) || !m_typed_meanwhile.empty();
}

int ReplayDriver::delay_ms() const { return m_session->animating() ? m_session->delay_ms() : m_pace.milliseconds; }

void ReplayDriver::lay_overlay()
{
    Overlay now = overlay_now();
    if (now == m_laid)
        return;
    m_laid = std::move(now);
    ++m_revision;
}

void ReplayDriver::handle(const KeyEvent& key)
{
    take(key);
    lay_overlay();
}

void ReplayDriver::tick()
{
    take_tick();
    lay_overlay();
}

void ReplayDriver::work()
{
    take_work();
    lay_overlay();
}

ReplayGuardFacts ReplayDriver::guard_facts() const
{
    return {paced(), m_pace.kind == ReplayPace::Kind::on_space, m_session->takes_typed_text()};
}

void ReplayDriver::take(const KeyEvent& key)
{
    // "GOAL REACHED: …" and "GOAL skipped: …" stay on the message line until the next key.
    if (!waiting_goal())
        m_session->say_goal({});
    m_last_action = replay_action(state(), replay_key_of(key), guard_facts());
    if (m_last_action)
        act(*m_last_action, key);
    after_change();
}

void ReplayDriver::act(ReplayAction action, const KeyEvent& key)
{
    switch (action) {
    case ReplayAction::wait_for_unasked: m_typed_meanwhile.push_back(key); return;
    case ReplayAction::play_step: play_scripted(); return;
    case ReplayAction::name_keys: return; // overlay_now(): the badge names them until the next key
    case ReplayAction::to_session: to_session(key); return;
    case ReplayAction::to_keyboard:
        stop();
        to_session(key);
        return;
    case ReplayAction::release:
        m_mode = Mode::left;
        to_session(key);
        return;
    case ReplayAction::hold_step: m_mode = Mode::step_held; return;
    case ReplayAction::next_caption: play_to_next_caption(); return;
    case ReplayAction::skip_goal: skip_goal(); return;
    case ReplayAction::back: {
        const std::optional<std::size_t> caption = caption_on_row();
        if (caption && *caption > 0)
            go_to_caption(*caption - 1, "PGUP");
        else
            go_to_start("PGUP");
        return;
    }
    case ReplayAction::back_to_shown: {
        const std::optional<std::size_t> caption = caption_on_row();
        if (caption)
            go_to_caption(*caption, "PGUP");
        else
            go_to_start("PGUP");
        return;
    }
    case ReplayAction::forward_to_next: {
        const std::optional<std::size_t> caption = caption_on_row();
        go_to_caption(caption ? *caption + 1 : 0, "PGDN");
        return;
    }
    case ReplayAction::first: go_to_caption(0, "HOME"); return;
    case ReplayAction::hand_over:
        stop();
        m_step_label = "ESC";
        return;
    case ReplayAction::ask_to_leave: m_mode = Mode::asking_to_leave; return;
    case ReplayAction::leave: leave_exercise(); return;
    case ReplayAction::stay: m_mode = Mode::at_goal; return;
    case ReplayAction::tell_end: m_mode = Mode::end_told; return;
    }
}

void ReplayDriver::take_tick()
{
    if (m_session->animating()) {
        // A frame counts as a key: its points are the teacher's key frames' (fixed by the exercise),
        // and frames come only from keys that start an animation.
        m_work_done += m_session->key_work();
        m_session->tick();
    }
    else if (script_ready() && paced_every())
        play_scripted();
    after_change();
}

void ReplayDriver::take_work()
{
    if (m_session->busy()) {
        m_session->work();
    } else if (m_audience == ReplayAudience::headless) {
        play_headless();
        return;
    } else if (script_ready() && plays_unasked()) {
        // A held Space is taken by the step it plays.
        if (m_mode == Mode::step_held && !mid_step())
            m_mode = Mode::deck;
        play_scripted();
    } else if (!m_typed_meanwhile.empty()) {
        const KeyEvent key = m_typed_meanwhile.front();
        m_typed_meanwhile.pop_front();
        take(key);
        return;
    }
    after_change();
}

// Headless: the captions and goals before the next key reached (the moment the headless transcript
// has always printed a caption), then that key played.
void ReplayDriver::play_headless()
{
    settle();
    play_scripted();
}

bool ReplayDriver::next_work_keeps_step() const
{
    // Its captions and goals, reached first (settle), change the message line, never the step.
    return m_audience == ReplayAudience::headless && !m_session->working() && playing() && !m_session->animating() &&
           m_session->keeps_step(m_script.events[m_played]);
}

ProgramScreen ReplayDriver::screen() const
{
    ProgramScreen screen = m_session->screen();
    // The help fills the screen from its title to "Any key closes this help.": a caption there
    // would push the title off, the badge cover its first key line. Both come back as it closes.
    if (m_session->showing_help())
        return screen;
    screen.caption = m_laid.caption;
    screen.badge = m_laid.badge;
    screen.badge_place = m_laid.place;
    return screen;
}

ReplayDriver::Overlay ReplayDriver::overlay_now() const
{
    if (m_mode == Mode::asking_to_leave)
        return {std::string(leave_exercise_question), {}, {}};
    if (m_mode == Mode::left)
        return {};
    Overlay over;
    const std::optional<std::size_t> caption = caption_on_row();
    const bool typed_since_hand_over = m_mode == Mode::keyboard && m_handled.size() > m_handed_over_at;
    if (caption && !typed_since_hand_over)
        over.caption = caption_text(*caption);
    if (m_mode == Mode::end_told)
        over.caption = end_of_script_caption;
    if (!paced())
        return over;
    over.badge = m_step_label;
    over.place = place_in_badge(caption);
    if (m_last_action == ReplayAction::name_keys) {
        // The badge with the keys fits the 80-column top edge: a long step label gives way.
        constexpr std::size_t label_room = 12;
        if (over.badge.size() > label_room) {
            std::size_t cut = label_room - 3;
            while (cut > 0 && (static_cast<unsigned char>(over.badge[cut]) & 0xC0) == 0x80)
                --cut; // not inside a character
            over.badge = over.badge.substr(0, cut) + "...";
        }
    }
    return over;
}

std::string ReplayDriver::place_in_badge(std::optional<std::size_t> caption) const
{
    if (m_mode == Mode::keyboard)
        return std::string(replay_keys_keyboard);
    if (m_last_action == ReplayAction::name_keys)
        return std::string(m_pace.kind == ReplayPace::Kind::on_space ? replay_keys_on_space : replay_keys_timed);
    const std::size_t captions = m_script.captions.size();
    if (caption)
        return "caption " + std::to_string(*caption + 1) + " of " + std::to_string(captions);
    return captions > 0 ? "caption 0 of " + std::to_string(captions) : std::string();
}

void ReplayDriver::finish()
{
    if (m_audience == ReplayAudience::terminal) {
        // The program ends (the session did, or a signal or a lost terminal ended it): a goal not
        // judged yet is judged as it stands, as the headless recheck of the recording judges it.
        if (m_open) {
            const bool waiting = waiting_goal().has_value();
            follow_open_goal();
            judge_open_goal(open_goal_as_it_stands());
            if (waiting)
                m_mode = Mode::left;
        }
    } else {
        settle();
        settle_headless(m_script.events.size());
        end_caption();
    }
    lay_overlay();
}

void ReplayDriver::play_scripted()
{
    if (m_last_action == ReplayAction::name_keys)
        m_last_action.reset(); // the badge names the step again
    if (keyless_caption_due()) {
        ++m_captions_shown;
        m_step_label.clear(); // no key played: the badge gives the place alone
        return;
    }
    if (m_played >= m_script.events.size())
        return;
    show_captions_through(m_played);
    // The caption just shown poses a goal here: it waits (settle) before any key is played.
    if (goal_due())
        return;
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

// Esc during a paced replay: the keyboard is the presenter's, the caption on the row stays.
void ReplayDriver::stop()
{
    m_step_end = m_run_to = m_played;
    m_mode = Mode::keyboard;
    m_handed_over_at = m_handled.size();
}

std::optional<std::size_t> ReplayDriver::caption_on_row() const
{
    // A goal waiting shows its task, the caption before its GOAL line, not one that closes it.
    if (const std::optional<std::size_t> goal = waiting_goal()) {
        const std::size_t before = m_script.goals[*goal].captions_before;
        return before > 0 ? std::optional<std::size_t>(before - 1) : std::nullopt;
    }
    if (paced())
        return m_captions_shown > 0 ? std::optional<std::size_t>(m_captions_shown - 1) : std::nullopt;
    const ScriptCaption* caption = caption_at(m_script, m_played);
    if (caption == nullptr)
        return std::nullopt;
    return static_cast<std::size_t>(caption - m_script.captions.data());
}

std::size_t ReplayDriver::caption_keys_end(std::size_t caption) const
{
    const std::vector<ScriptCaption>& captions = m_script.captions;
    std::size_t end = caption + 1 < captions.size() ? captions[caption + 1].before_event : m_script.events.size();
    // A task's keys end at its GOAL line: what follows is the answer, the student's.
    for (const ScriptGoal& goal : m_script.goals)
        if (goal.captions_before == caption + 1)
            end = std::min(end, goal.before_event);
    return end;
}

bool ReplayDriver::goal_due() const
{
    const std::vector<ScriptGoal>& goals = m_script.goals;
    return m_audience == ReplayAudience::terminal && m_next_goal < goals.size() &&
           goals[m_next_goal].before_event <= m_played && task_shown(m_next_goal);
}

bool ReplayDriver::caption_due() const
{
    return paced() && m_captions_shown < m_script.captions.size() &&
           m_script.captions[m_captions_shown].before_event <= m_played;
}

bool ReplayDriver::keyless_caption_due() const
{
    return caption_due() && caption_keys_end(m_captions_shown) <= m_played;
}

void ReplayDriver::show_captions_through(std::size_t event)
{
    if (!paced())
        return;
    const std::vector<ScriptCaption>& captions = m_script.captions;
    while (m_captions_shown < captions.size() && captions[m_captions_shown].before_event <= event)
        ++m_captions_shown;
}

bool ReplayDriver::task_shown(std::size_t goal) const
{
    return !paced() || m_captions_shown >= m_script.goals[goal].captions_before;
}

} // namespace apcs
