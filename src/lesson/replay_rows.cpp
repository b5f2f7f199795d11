#include "apcs/lesson/replay_rows.h"

#include <algorithm>
#include <array>

namespace apcs {

namespace {

using S = ReplayState;
using K = ReplayKey;
using G = ReplayGuard;
using A = ReplayAction;

// One row a line, grouped by state. Where a key means one thing in a paced lesson and another in a
// replay at once, or one thing on the staff and another at a prompt, two rows with opposite guards.
constexpr std::array rows{
    // The keys that play unasked are the script's: a key typed meanwhile is read after them.
    ReplayRow{S::playing_unasked, K::space, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::page_down, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::page_up, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::home, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::right_bracket, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::left_bracket, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::escape, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::frame_step, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::letter_q, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::letter_y, G::always, A::wait_for_unasked},
    ReplayRow{S::playing_unasked, K::other, G::always, A::wait_for_unasked},

    // The presenter's deck (SPEC §3.1): the keys are the script's, a stray key names those.
    ReplayRow{S::waiting_for_space, K::space, G::always, A::play_step},
    ReplayRow{S::waiting_for_space, K::page_down, G::always, A::next_caption},
    ReplayRow{S::waiting_for_space, K::right_bracket, G::always, A::next_caption},
    ReplayRow{S::waiting_for_space, K::page_up, G::always, A::back},
    ReplayRow{S::waiting_for_space, K::left_bracket, G::always, A::back},
    ReplayRow{S::waiting_for_space, K::home, G::always, A::first},
    ReplayRow{S::waiting_for_space, K::escape, G::always, A::hand_over},
    ReplayRow{S::waiting_for_space, K::frame_step, G::always, A::name_keys},
    ReplayRow{S::waiting_for_space, K::letter_q, G::always, A::name_keys},
    ReplayRow{S::waiting_for_space, K::letter_y, G::always, A::name_keys},
    ReplayRow{S::waiting_for_space, K::other, G::always, A::name_keys},

    ReplayRow{S::waiting_for_clock, K::space, G::always, A::name_keys},
    ReplayRow{S::waiting_for_clock, K::page_down, G::always, A::next_caption},
    ReplayRow{S::waiting_for_clock, K::right_bracket, G::always, A::next_caption},
    ReplayRow{S::waiting_for_clock, K::page_up, G::always, A::back},
    ReplayRow{S::waiting_for_clock, K::left_bracket, G::always, A::back},
    ReplayRow{S::waiting_for_clock, K::home, G::always, A::first},
    ReplayRow{S::waiting_for_clock, K::escape, G::always, A::hand_over},
    ReplayRow{S::waiting_for_clock, K::frame_step, G::always, A::name_keys},
    ReplayRow{S::waiting_for_clock, K::letter_q, G::always, A::name_keys},
    ReplayRow{S::waiting_for_clock, K::letter_y, G::always, A::name_keys},
    ReplayRow{S::waiting_for_clock, K::other, G::always, A::name_keys},

    // The session splits or refines: Esc is its (it cancels a split); the deck keys stay the deck's.
    ReplayRow{S::session_working, K::space, G::always, A::to_session},
    ReplayRow{S::session_working, K::page_down, G::paced, A::next_caption},
    ReplayRow{S::session_working, K::page_down, G::at_once, A::to_session},
    ReplayRow{S::session_working, K::page_up, G::paced, A::back},
    ReplayRow{S::session_working, K::page_up, G::at_once, A::to_session},
    ReplayRow{S::session_working, K::home, G::paced, A::first},
    ReplayRow{S::session_working, K::home, G::at_once, A::to_session},
    ReplayRow{S::session_working, K::right_bracket, G::always, A::to_session},
    ReplayRow{S::session_working, K::left_bracket, G::always, A::to_session},
    ReplayRow{S::session_working, K::escape, G::always, A::to_session},
    ReplayRow{S::session_working, K::frame_step, G::always, A::to_session},
    ReplayRow{S::session_working, K::letter_q, G::always, A::to_session},
    ReplayRow{S::session_working, K::letter_y, G::always, A::to_session},
    ReplayRow{S::session_working, K::other, G::always, A::to_session},

    // The frames play: the player's keys are the session's (, . pause and step, Esc stops, R
    // replays); a Space in a lesson stepped by Space is its next step, held until the frames end
    // (the player's pause key would stop the lesson).
    ReplayRow{S::animation_playing, K::space, G::on_space, A::hold_step},
    ReplayRow{S::animation_playing, K::space, G::not_on_space, A::to_session},
    ReplayRow{S::animation_playing, K::page_down, G::paced, A::next_caption},
    ReplayRow{S::animation_playing, K::page_down, G::at_once, A::to_session},
    ReplayRow{S::animation_playing, K::page_up, G::paced, A::back},
    ReplayRow{S::animation_playing, K::page_up, G::at_once, A::to_session},
    ReplayRow{S::animation_playing, K::home, G::paced, A::first},
    ReplayRow{S::animation_playing, K::home, G::at_once, A::to_session},
    ReplayRow{S::animation_playing, K::right_bracket, G::always, A::to_session},
    ReplayRow{S::animation_playing, K::left_bracket, G::always, A::to_session},
    ReplayRow{S::animation_playing, K::escape, G::always, A::to_session},
    ReplayRow{S::animation_playing, K::frame_step, G::always, A::to_session},
    ReplayRow{S::animation_playing, K::letter_q, G::always, A::to_session},
    ReplayRow{S::animation_playing, K::letter_y, G::always, A::to_session},
    ReplayRow{S::animation_playing, K::other, G::always, A::to_session},

    // Only a lesson stepped by Space holds a step.
    ReplayRow{S::animation_step_held, K::space, G::always, A::hold_step},
    ReplayRow{S::animation_step_held, K::page_down, G::always, A::next_caption},
    ReplayRow{S::animation_step_held, K::page_up, G::always, A::back},
    ReplayRow{S::animation_step_held, K::home, G::always, A::first},
    ReplayRow{S::animation_step_held, K::right_bracket, G::always, A::to_session},
    ReplayRow{S::animation_step_held, K::left_bracket, G::always, A::to_session},
    ReplayRow{S::animation_step_held, K::escape, G::always, A::to_session},
    ReplayRow{S::animation_step_held, K::frame_step, G::always, A::to_session},
    ReplayRow{S::animation_step_held, K::letter_q, G::always, A::to_session},
    ReplayRow{S::animation_step_held, K::letter_y, G::always, A::to_session},
    ReplayRow{S::animation_step_held, K::other, G::always, A::to_session},

    // Paused by , or .: each further press steps one frame, Space resumes (SPEC §3.2); the script
    // waits for the frames' end.
    ReplayRow{S::animation_paused, K::space, G::always, A::to_session},
    ReplayRow{S::animation_paused, K::page_down, G::paced, A::next_caption},
    ReplayRow{S::animation_paused, K::page_down, G::at_once, A::to_session},
    ReplayRow{S::animation_paused, K::page_up, G::paced, A::back},
    ReplayRow{S::animation_paused, K::page_up, G::at_once, A::to_session},
    ReplayRow{S::animation_paused, K::home, G::paced, A::first},
    ReplayRow{S::animation_paused, K::home, G::at_once, A::to_session},
    ReplayRow{S::animation_paused, K::right_bracket, G::always, A::to_session},
    ReplayRow{S::animation_paused, K::left_bracket, G::always, A::to_session},
    ReplayRow{S::animation_paused, K::escape, G::always, A::to_session},
    ReplayRow{S::animation_paused, K::frame_step, G::always, A::to_session},
    ReplayRow{S::animation_paused, K::letter_q, G::always, A::to_session},
    ReplayRow{S::animation_paused, K::letter_y, G::always, A::to_session},
    ReplayRow{S::animation_paused, K::other, G::always, A::to_session},

    // At a goal the keys are the student's; on the staff Esc keeps its meaning (SPEC §3.1).
    ReplayRow{S::at_goal, K::space, G::always, A::to_session},
    ReplayRow{S::at_goal, K::page_down, G::paced, A::skip_goal},
    ReplayRow{S::at_goal, K::page_down, G::at_once, A::to_session},
    ReplayRow{S::at_goal, K::page_up, G::paced, A::back},
    ReplayRow{S::at_goal, K::page_up, G::at_once, A::to_session},
    ReplayRow{S::at_goal, K::home, G::paced, A::first},
    ReplayRow{S::at_goal, K::home, G::at_once, A::to_session},
    ReplayRow{S::at_goal, K::right_bracket, G::always, A::to_session},
    ReplayRow{S::at_goal, K::left_bracket, G::always, A::to_session},
    ReplayRow{S::at_goal, K::escape, G::always, A::to_session},
    ReplayRow{S::at_goal, K::frame_step, G::always, A::to_session},
    // A goal the student cannot reach must not trap the class; where text is typed q is a letter.
    ReplayRow{S::at_goal, K::letter_q, G::not_typing, A::ask_to_leave},
    ReplayRow{S::at_goal, K::letter_q, G::typing, A::to_session},
    ReplayRow{S::at_goal, K::letter_y, G::always, A::to_session},
    ReplayRow{S::at_goal, K::other, G::always, A::to_session},

    ReplayRow{S::asking_to_leave, K::letter_y, G::always, A::leave},
    ReplayRow{S::asking_to_leave, K::space, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::page_down, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::page_up, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::home, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::right_bracket, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::left_bracket, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::escape, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::frame_step, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::letter_q, G::always, A::stay},
    ReplayRow{S::asking_to_leave, K::other, G::always, A::stay},

    // The presenter's keyboard (SPEC §3.2): PgUp, PgDn and Home give it back to the lesson.
    ReplayRow{S::keyboard, K::page_up, G::always, A::back_to_shown},
    ReplayRow{S::keyboard, K::page_down, G::always, A::forward_to_next},
    ReplayRow{S::keyboard, K::home, G::always, A::first},
    ReplayRow{S::keyboard, K::space, G::always, A::to_session},
    ReplayRow{S::keyboard, K::right_bracket, G::always, A::to_session},
    ReplayRow{S::keyboard, K::left_bracket, G::always, A::to_session},
    ReplayRow{S::keyboard, K::escape, G::always, A::to_session},
    ReplayRow{S::keyboard, K::frame_step, G::always, A::to_session},
    ReplayRow{S::keyboard, K::letter_q, G::always, A::to_session},
    ReplayRow{S::keyboard, K::letter_y, G::always, A::to_session},
    ReplayRow{S::keyboard, K::other, G::always, A::to_session},

    // The script played: paced, the presenter may still go back; at once the session plays on.
    ReplayRow{S::end, K::space, G::paced, A::tell_end},
    ReplayRow{S::end, K::space, G::at_once, A::release},
    ReplayRow{S::end, K::page_down, G::paced, A::tell_end},
    ReplayRow{S::end, K::page_down, G::at_once, A::release},
    ReplayRow{S::end, K::page_up, G::paced, A::back},
    ReplayRow{S::end, K::page_up, G::at_once, A::release},
    ReplayRow{S::end, K::home, G::paced, A::first},
    ReplayRow{S::end, K::home, G::at_once, A::release},
    ReplayRow{S::end, K::right_bracket, G::paced, A::to_keyboard},
    ReplayRow{S::end, K::right_bracket, G::at_once, A::release},
    ReplayRow{S::end, K::left_bracket, G::paced, A::to_keyboard},
    ReplayRow{S::end, K::left_bracket, G::at_once, A::release},
    ReplayRow{S::end, K::escape, G::paced, A::to_keyboard},
    ReplayRow{S::end, K::escape, G::at_once, A::release},
    ReplayRow{S::end, K::frame_step, G::paced, A::to_keyboard},
    ReplayRow{S::end, K::frame_step, G::at_once, A::release},
    ReplayRow{S::end, K::letter_q, G::paced, A::to_keyboard},
    ReplayRow{S::end, K::letter_q, G::at_once, A::release},
    ReplayRow{S::end, K::letter_y, G::paced, A::to_keyboard},
    ReplayRow{S::end, K::letter_y, G::at_once, A::release},
    ReplayRow{S::end, K::other, G::paced, A::to_keyboard},
    ReplayRow{S::end, K::other, G::at_once, A::release},

    // Only a paced lesson tells its end; PgUp there returns to the caption it replaced (SPEC §3.2).
    ReplayRow{S::end_told, K::page_up, G::always, A::back_to_shown},
    ReplayRow{S::end_told, K::home, G::always, A::first},
    ReplayRow{S::end_told, K::space, G::always, A::to_keyboard},
    ReplayRow{S::end_told, K::right_bracket, G::always, A::to_keyboard},
    ReplayRow{S::end_told, K::left_bracket, G::always, A::to_keyboard},
    ReplayRow{S::end_told, K::escape, G::always, A::to_keyboard},
    ReplayRow{S::end_told, K::frame_step, G::always, A::to_keyboard},
    ReplayRow{S::end_told, K::letter_q, G::always, A::to_keyboard},
    ReplayRow{S::end_told, K::letter_y, G::always, A::to_keyboard},
    ReplayRow{S::end_told, K::other, G::always, A::to_keyboard},

    ReplayRow{S::left, K::space, G::always, A::to_session},
    ReplayRow{S::left, K::page_down, G::always, A::to_session},
    ReplayRow{S::left, K::page_up, G::always, A::to_session},
    ReplayRow{S::left, K::home, G::always, A::to_session},
    ReplayRow{S::left, K::right_bracket, G::always, A::to_session},
    ReplayRow{S::left, K::left_bracket, G::always, A::to_session},
    ReplayRow{S::left, K::escape, G::always, A::to_session},
    ReplayRow{S::left, K::frame_step, G::always, A::to_session},
    ReplayRow{S::left, K::letter_q, G::always, A::to_session},
    ReplayRow{S::left, K::letter_y, G::always, A::to_session},
    ReplayRow{S::left, K::other, G::always, A::to_session},
};

constexpr std::array ignores{
    ReplayIgnore{S::end_told, K::page_down, "nothing follows the end, and the caption row says so already"},
};

} // namespace

std::span<const ReplayRow> replay_rows() { return rows; }
std::span<const ReplayIgnore> replay_ignores() { return ignores; }

bool guard_holds(ReplayGuard guard, const ReplayGuardFacts& facts)
{
    switch (guard) {
    case ReplayGuard::always: return true;
    case ReplayGuard::paced: return facts.paced;
    case ReplayGuard::at_once: return !facts.paced;
    case ReplayGuard::on_space: return facts.on_space;
    case ReplayGuard::not_on_space: return !facts.on_space;
    case ReplayGuard::typing: return facts.typing;
    case ReplayGuard::not_typing: return !facts.typing;
    }
    return false;
}

ReplayKey replay_key_of(const KeyEvent& key)
{
    switch (key.key) {
    case Key::space: return ReplayKey::space;
    case Key::page_down: return ReplayKey::page_down;
    case Key::page_up: return ReplayKey::page_up;
    case Key::home: return ReplayKey::home;
    case Key::escape: return ReplayKey::escape;
    default: break;
    }
    if (key == KeyEvent::typed(U']'))
        return ReplayKey::right_bracket;
    if (key == KeyEvent::typed(U'['))
        return ReplayKey::left_bracket;
    if (key == KeyEvent::typed(U',') || key == KeyEvent::typed(U'.'))
        return ReplayKey::frame_step;
    if (key == KeyEvent::typed(U'q') || key == KeyEvent::typed(U'Q'))
        return ReplayKey::letter_q;
    if (key == KeyEvent::typed(U'y') || key == KeyEvent::typed(U'Y'))
        return ReplayKey::letter_y;
    return ReplayKey::other;
}

std::optional<ReplayAction> replay_action(ReplayState state, ReplayKey key, const ReplayGuardFacts& facts)
{
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const ReplayRow& candidate) {
        return candidate.state == state && candidate.key == key && guard_holds(candidate.guard, facts);
    });
    if (row == rows.end())
        return std::nullopt;
    return row->action;
}

std::string_view replay_state_name(ReplayState state)
{
    constexpr std::array<std::string_view, replay_state_count> names{
        "playing unasked", "waiting for Space", "waiting for the clock", "session working",
        "animation playing", "animation, a step held", "animation paused", "at a goal",
        "asking to leave", "the presenter's keyboard", "the end", "the end told", "left"};
    return names[static_cast<std::size_t>(state)];
}

std::string_view replay_key_name(ReplayKey key)
{
    constexpr std::array<std::string_view, replay_key_count> names{"Space", "PgDn", "PgUp", "Home", "]", "[",
                                                                   "Esc",   ", or .", "q",  "y",    "another key"};
    return names[static_cast<std::size_t>(key)];
}

std::string_view replay_action_name(ReplayAction action)
{
    constexpr std::array<std::string_view, 18> names{
        "wait for the unasked keys", "play the next step", "name the keys", "to the session",
        "to the session, the keyboard the presenter's", "to the session, the replay over", "hold the next step",
        "next caption", "skip the goal", "back a caption", "back to the caption shown", "forward to the next caption",
        "first caption", "hand the keyboard over", "ask to leave", "leave", "stay at the goal", "tell the end"};
    return names[static_cast<std::size_t>(action)];
}

std::string_view replay_guard_name(ReplayGuard guard)
{
    constexpr std::array<std::string_view, 7> names{"always", "paced", "at once", "on Space", "not on Space",
                                                    "typing", "not typing"};
    return names[static_cast<std::size_t>(guard)];
}

} // namespace apcs
