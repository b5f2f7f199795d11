#pragma once

#include "apcs/formats/key_event.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace apcs {

// The states a key typed during a replay meets (SPEC §3.1, §3.2), the replay's own mode read
// together with the session's: a paced lesson waits for Space, plays keys unasked, is held by an
// animation, waits at a goal, has handed the keyboard over, or has played its script.
enum class ReplayState : std::uint8_t {
    playing_unasked,     // the preamble, a step's rest, PgDn's run: keys typed meanwhile wait for its end
    waiting_for_space,   // --pace step: the next step waits for Space
    waiting_for_clock,   // --pace MS: the next step waits for the clock
    session_working,     // the session splits or refines a picture between the script's keys (Session::working)
    animation_playing,   // the session plays the frames
    animation_step_held, // the frames play and a Space waits to be the next step when they end
    animation_paused,    // the frames are paused by , or . (each press steps one frame)
    at_goal,             // a GOAL that does not hold yet: the student's keys shape the path
    asking_to_leave,     // q at a goal: "Leave the exercise ? (Y/N)"
    keyboard,            // Esc, or a key typed after the end: the presenter's keys, until PgUp PgDn Home
    end,                 // the script's keys are all played
    end_told,            // and "End of the script" is on the caption row
    left,                // the exercise was left (Y): the keyboard is the session's for good
};
inline constexpr std::size_t replay_state_count = 13;

// The keys as the replay tells them apart; every other key is `other`.
enum class ReplayKey : std::uint8_t {
    space,
    page_down,
    page_up,
    home,
    right_bracket, // ']': PgDn while the replay waits, the waypoint editor's key elsewhere
    left_bracket,  // '['
    escape,
    frame_step, // ',' and '.': the animation's frame keys
    letter_q,   // q or Q
    letter_y,   // y or Y
    other,
};
inline constexpr std::size_t replay_key_count = 11;

// What a row does.
enum class ReplayAction : std::uint8_t {
    wait_for_unasked, // kept, and taken once the keys that play unasked have played, as if typed then
    play_step,        // the script's next step
    name_keys,        // the badge names the keys the replay takes, until the next key
    to_session,       // the session's key (a student's or presenter's, recorded)
    to_keyboard,      // the session's key, and the keyboard the presenter's (state keyboard)
    release,          // the session's key, and the replay over: nothing of it shown again (state left)
    hold_step,        // the next step, played once the animation ends
    next_caption,     // PgDn: the next caption shown, its keys played, stopping before the one after
    skip_goal,        // PgDn at a goal: "GOAL skipped: …", the closing caption "(skipped) …"
    back,             // PgUp: to the previous caption's screen (before the first: the start)
    back_to_shown,    // PgUp after Esc or at the end: to the screen of the caption on the row
    forward_to_next,  // PgDn after Esc: to the next caption's screen, replayed from the inputs
    first,            // Home: to the first caption's screen
    hand_over,        // Esc: the keyboard is the presenter's, the caption stays
    ask_to_leave,     // q at a goal
    leave,            // Y to "Leave the exercise ?"
    stay,             // any other key to it: back to the goal
    tell_end,         // "End of the script: the keyboard is yours (PgUp, Home: back)"
};

// When a row holds: some keys mean one thing paced and another at once, or while text is typed.
enum class ReplayGuard : std::uint8_t {
    always,
    paced,        // --pace step or --pace MS
    at_once,      // no --pace: the deck keys are the session's
    on_space,     // --pace step
    not_on_space, // --pace MS, or at once
    typing,       // the session takes typed text (a prompt, the value field): q is a letter
    not_typing,
};

struct ReplayRow {
    ReplayState state;
    ReplayKey key;
    ReplayGuard guard;
    ReplayAction action;
};

// A key a state does not take, and why: nothing happens, on purpose.
struct ReplayIgnore {
    ReplayState state;
    ReplayKey key;
    std::string_view why;
};

// The chart: every (state, key) has rows whose guards cover every case, or one written ignore.
std::span<const ReplayRow> replay_rows();
std::span<const ReplayIgnore> replay_ignores();

// What the guards are tested against.
struct ReplayGuardFacts {
    bool paced = false;
    bool on_space = false;
    bool typing = false;
};
bool guard_holds(ReplayGuard guard, const ReplayGuardFacts& facts);

ReplayKey replay_key_of(const KeyEvent& key);
// The action of the first row for `key` in `state` whose guard holds; none for a written ignore.
std::optional<ReplayAction> replay_action(ReplayState state, ReplayKey key, const ReplayGuardFacts& facts);

std::string_view replay_state_name(ReplayState state);
std::string_view replay_key_name(ReplayKey key);
std::string_view replay_action_name(ReplayAction action);
std::string_view replay_guard_name(ReplayGuard guard);

} // namespace apcs
