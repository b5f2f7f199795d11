// The replay's chart (SPEC §3.1, §3.2): every (state, key) is a row or a written ignore, and a walk
// that brings a real replay into each state and presses each key there sees the row's effect.
#include "apcs/lesson/replay_rows.h"
#include "apcs/screens/replay_caption.h"

#include "support/replay_deck.h"
#include "support/replay_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <memory>
#include <set>
#include <sstream>
#include <vector>
#include <string>

using namespace apcs;
using test::Deck;
using test::data_folder;
using test::message_line;
using test::read_script;

namespace {

const std::string preamble = "ENTER ENTER\nTEXT 0 90 100\nENTER\nTEXT ani1.dat\nENTER ENTER\nSTART\n";

// Four captions of keys: the N to L example's two paths accepted, the surface fitted, the frames
// played and overlaid.
const KeyScript& deck_script()
{
    static const KeyScript script = test::parsed_deck(preamble + ";; one\n8 ENTER ENTER ENTER ENTER N\n"
                                                      ";; two\nY\nTEXT ani4.dat\nENTER ENTER\n8 ENTER ENTER ENTER ENTER N\n"
                                                      "ENTER\n;; three\nSPACE\n;; four\nSPACE\n");
    return script;
}

const KeyScript& exercise_script()
{
    static const KeyScript script = read_script(data_folder / "exercises" / "exercise-1-tension.keys");
    return script;
}

const ReplayPace on_space{ReplayPace::Kind::on_space, 0};

// Key frames whose split takes more than one of the session's steps of work.
MemoryFiles hundred_point_keys()
{
    MemoryFiles files;
    std::string key1 = "PART line OPEN\n";
    std::string key2 = "PART line OPEN\n";
    for (int point = 0; point < 100; ++point) {
        key1 += "0 " + std::to_string(point) + " 0\n";
        key2 += "0 " + std::to_string(point) + " 10\n";
    }
    files.files["key1.dat"] = key1;
    files.files["key2.dat"] = key2;
    return files;
}

std::unique_ptr<Deck> deck_at(const KeyScript& script, const std::string& example, ReplayPace pace = on_space,
                              Animations animations = Animations::play_through)
{
    return std::make_unique<Deck>(script, example, pace, animations);
}

void page_down_to_the_end(Deck& deck)
{
    for (int press = 0; press < 10 && deck.replay->state() != ReplayState::end; ++press)
        deck.press(KeyEvent::of(Key::page_down));
}

std::unique_ptr<Deck> at_goal(ReplayPace pace = on_space)
{
    auto deck = deck_at(exercise_script(), "exercises", pace);
    for (int step = 0; step < 20 && deck->replay->state() != ReplayState::at_goal; ++step)
        deck->press(KeyEvent::of(Key::space));
    return deck;
}

// The animation of deck_script, stopped at as the terminal does until its clock ticks.
std::unique_ptr<Deck> at_animation()
{
    auto deck = deck_at(deck_script(), "n-to-l", on_space, Animations::stop_at);
    for (int step = 0; step < 3; ++step)
        deck->press(KeyEvent::of(Key::page_down)); // the last plays caption three's SPACE
    return deck;
}

// A way into each state, and the replay's facts there.
struct Reach {
    ReplayState state;
    std::string how;
    std::function<std::unique_ptr<Deck>()> make;
};

std::vector<Reach> ways_in()
{
    return {
        {ReplayState::playing_unasked, "PgDn, its run not yet played",
         [] {
             auto deck = deck_at(deck_script(), "n-to-l");
             deck->replay->handle(KeyEvent::of(Key::page_down));
             return deck;
         }},
        {ReplayState::waiting_for_space, "a lesson stepped by Space", [] { return deck_at(deck_script(), "n-to-l"); }},
        {ReplayState::waiting_for_clock, "a lesson stepped by the clock",
         [] { return deck_at(deck_script(), "n-to-l", {ReplayPace::Kind::every, 100}, Animations::stop_at); }},
        {ReplayState::session_working, "the split of key frames of 100 points, after KEY2",
         [] {
             static const KeyScript split = test::parsed_deck("ENTER\nSTART\n;; one\nENTER\n;; two\nTEXT 0 90 100\n");
             auto deck = std::make_unique<Deck>(split, hundred_point_keys(), on_space, Animations::play_through,
                                                SessionSettings{});
             deck->replay->handle(KeyEvent::of(Key::space)); // the split writes 64 path files a step
             return deck;
         }},
        {ReplayState::animation_playing, "the frames playing", at_animation},
        {ReplayState::animation_step_held, "Space while the frames play",
         [] {
             auto deck = at_animation();
             deck->press(KeyEvent::of(Key::space));
             return deck;
         }},
        {ReplayState::animation_paused, ". while the frames play",
         [] {
             auto deck = at_animation();
             deck->press(KeyEvent::typed(U'.'));
             return deck;
         }},
        {ReplayState::at_goal, "exercise 1's goal", [] { return at_goal(); }},
        {ReplayState::at_goal, "exercise 1's goal, played at once", [] { return at_goal(ReplayPace{}); }},
        {ReplayState::at_goal, "exercise 1's goal, the value field open",
         [] {
             auto deck = at_goal();
             deck->press(KeyEvent::typed(U'='));
             return deck;
         }},
        {ReplayState::asking_to_leave, "q at a goal",
         [] {
             auto deck = at_goal();
             deck->press(KeyEvent::typed(U'q'));
             return deck;
         }},
        {ReplayState::keyboard, "Esc", [] {
             auto deck = deck_at(deck_script(), "n-to-l");
             deck->press(KeyEvent::of(Key::page_down));
             deck->press(KeyEvent::of(Key::escape));
             return deck;
         }},
        {ReplayState::end, "PgDn to the end",
         [] {
             auto deck = deck_at(deck_script(), "n-to-l");
             page_down_to_the_end(*deck);
             return deck;
         }},
        {ReplayState::end, "a script played at once",
         [] { return deck_at(deck_script(), "n-to-l", ReplayPace{}); }},
        {ReplayState::end_told, "PgDn past the end",
         [] {
             auto deck = deck_at(deck_script(), "n-to-l");
             page_down_to_the_end(*deck);
             deck->press(KeyEvent::of(Key::page_down));
             return deck;
         }},
        {ReplayState::left, "Y to Leave the exercise ?",
         [] {
             auto deck = at_goal();
             deck->press(KeyEvent::typed(U'q'));
             deck->press(KeyEvent::typed(U'Y'));
             return deck;
         }},
    };
}

KeyEvent key_of(ReplayKey key)
{
    switch (key) {
    case ReplayKey::space: return KeyEvent::of(Key::space);
    case ReplayKey::page_down: return KeyEvent::of(Key::page_down);
    case ReplayKey::page_up: return KeyEvent::of(Key::page_up);
    case ReplayKey::home: return KeyEvent::of(Key::home);
    case ReplayKey::right_bracket: return KeyEvent::typed(U']');
    case ReplayKey::left_bracket: return KeyEvent::typed(U'[');
    case ReplayKey::escape: return KeyEvent::of(Key::escape);
    case ReplayKey::frame_step: return KeyEvent::typed(U'.');
    case ReplayKey::letter_q: return KeyEvent::typed(U'q');
    case ReplayKey::letter_y: return KeyEvent::typed(U'y');
    case ReplayKey::other: return KeyEvent::typed(U'x');
    }
    return KeyEvent::typed(U'x');
}

// What the replay shows and holds, before and after a key.
struct Seen {
    std::size_t handled = 0;
    std::optional<KeyEvent> last_handled;
    ReplayState state{};
    std::string caption;
    std::string badge;
    std::string place;
    std::string message;
    std::size_t played_captions = 0; // the caption on the row, 1-based, 0 before the first

    static Seen of(const ReplayDriver& replay)
    {
        const ProgramScreen screen = replay.screen();
        Seen seen{replay.handled().size(), std::nullopt, replay.state(), screen.caption, screen.badge,
                  screen.badge_place, message_line(replay), 0};
        if (!replay.handled().empty())
            seen.last_handled = replay.handled().back();
        return seen;
    }
};

// The effect the row's action must have had, the key pressed in `before`, `after` right after it.
void check_effect(ReplayAction action, const KeyEvent& key, const Seen& before, const Seen& after, bool typing)
{
    const bool reached_session = after.handled == before.handled + 1 && after.last_handled == key;
    switch (action) {
    case ReplayAction::wait_for_unasked: REQUIRE(after.handled == before.handled); break;
    case ReplayAction::play_step: REQUIRE(after.handled > before.handled); break;
    case ReplayAction::name_keys:
        REQUIRE(after.handled == before.handled);
        REQUIRE((after.place == replay_keys_on_space || after.place == replay_keys_timed));
        break;
    case ReplayAction::to_session: REQUIRE(reached_session); break;
    case ReplayAction::to_keyboard:
        REQUIRE(reached_session);
        REQUIRE(after.state == ReplayState::keyboard);
        REQUIRE(after.place == replay_keys_keyboard);
        break;
    case ReplayAction::release:
        REQUIRE(reached_session);
        REQUIRE(after.state == ReplayState::left);
        REQUIRE(after.caption.empty());
        break;
    case ReplayAction::hold_step:
        REQUIRE(after.handled == before.handled);
        REQUIRE(after.state == ReplayState::animation_step_held);
        break;
    case ReplayAction::next_caption:
        REQUIRE(after.handled == before.handled); // the run plays after the key
        REQUIRE(after.state != ReplayState::keyboard);
        break;
    case ReplayAction::skip_goal:
        // The value field open keeps the message line; the caption row says it all the same.
        REQUIRE((after.message.starts_with("GOAL skipped: ") || typing));
        REQUIRE(after.caption.starts_with(skipped_caption_prefix));
        REQUIRE(after.state != ReplayState::at_goal);
        break;
    case ReplayAction::back:
    case ReplayAction::back_to_shown: REQUIRE(after.badge == "PGUP"); break;
    case ReplayAction::forward_to_next: REQUIRE(after.badge == "PGDN"); break;
    case ReplayAction::first:
        REQUIRE(after.badge == "HOME");
        REQUIRE(after.place.starts_with("caption 1 of "));
        break;
    case ReplayAction::hand_over:
        REQUIRE(after.handled == before.handled);
        REQUIRE(after.state == ReplayState::keyboard);
        REQUIRE(after.place == replay_keys_keyboard);
        REQUIRE(after.caption == before.caption);
        break;
    case ReplayAction::ask_to_leave: REQUIRE(after.caption == leave_exercise_question); break;
    case ReplayAction::leave: REQUIRE(after.state == ReplayState::left); break;
    case ReplayAction::stay:
        REQUIRE(after.handled == before.handled);
        REQUIRE(after.state == ReplayState::at_goal);
        break;
    case ReplayAction::tell_end:
        REQUIRE(after.handled == before.handled);
        REQUIRE(after.caption == end_of_script_caption);
        break;
    }
}

} // namespace

TEST_CASE("every (replay state, key) is one row for each case its guards tell apart, or a written ignore",
          "[lesson][replay][rows]")
{
    std::ostringstream missing;
    for (std::size_t s = 0; s < replay_state_count; ++s)
        for (std::size_t k = 0; k < replay_key_count; ++k) {
            const auto state = static_cast<ReplayState>(s);
            const auto key = static_cast<ReplayKey>(k);
            std::size_t ignores = 0;
            for (const ReplayIgnore& ignore : replay_ignores())
                if (ignore.state == state && ignore.key == key) {
                    ++ignores;
                    CHECK_FALSE(ignore.why.empty());
                }
            // Each case the guards can tell apart (on_space is a pace, so paced).
            for (const ReplayGuardFacts facts : {ReplayGuardFacts{false, false, false}, ReplayGuardFacts{false, false, true},
                                                 ReplayGuardFacts{true, false, false}, ReplayGuardFacts{true, false, true},
                                                 ReplayGuardFacts{true, true, false}, ReplayGuardFacts{true, true, true}}) {
                std::size_t rows = 0;
                for (const ReplayRow& row : replay_rows())
                    rows += row.state == state && row.key == key && guard_holds(row.guard, facts) ? 1U : 0U;
                if (rows + ignores != 1)
                    missing << replay_state_name(state) << " x " << replay_key_name(key) << " (paced " << facts.paced
                            << ", on Space " << facts.on_space << ", typing " << facts.typing << "): " << rows
                            << " rows, " << ignores << " ignores\n";
            }
        }
    INFO(missing.str());
    REQUIRE(missing.str().empty());
}

TEST_CASE("the keys as the replay tells them apart", "[lesson][replay][rows]")
{
    REQUIRE(replay_key_of(KeyEvent::typed(U',')) == ReplayKey::frame_step);
    REQUIRE(replay_key_of(KeyEvent::typed(U'.')) == ReplayKey::frame_step);
    REQUIRE(replay_key_of(KeyEvent::typed(U'Q')) == ReplayKey::letter_q);
    REQUIRE(replay_key_of(KeyEvent::typed(U'Y')) == ReplayKey::letter_y);
    REQUIRE(replay_key_of(KeyEvent::typed(U']')) == ReplayKey::right_bracket);
    REQUIRE(replay_key_of(KeyEvent::of(Key::page_down)) == ReplayKey::page_down);
    REQUIRE(replay_key_of(KeyEvent::of(Key::enter)) == ReplayKey::other);
    REQUIRE(replay_key_of(KeyEvent::typed(U'6')) == ReplayKey::other);
}

TEST_CASE("a walk through the chart: each state reached in a real replay, each key pressed there does what its row "
          "says",
          "[lesson][replay][rows]")
{
    std::set<std::size_t> states_walked;
    for (const Reach& way : ways_in())
        for (std::size_t k = 0; k < replay_key_count; ++k) {
            const auto key = static_cast<ReplayKey>(k);
            INFO(replay_state_name(way.state) << " (" << way.how << ") x " << replay_key_name(key));
            const std::unique_ptr<Deck> deck = way.make();
            ReplayDriver& replay = *deck->replay;
            INFO("state reached: " << replay_state_name(replay.state()) << ", session busy " << replay.session().busy());
            REQUIRE(replay.state() == way.state);
            states_walked.insert(static_cast<std::size_t>(way.state));
            const ReplayGuardFacts facts = replay.guard_facts();
            const std::optional<ReplayAction> expected = replay_action(way.state, key, facts);
            const Seen before = Seen::of(replay);
            const KeyEvent pressed = key_of(key);
            replay.handle(pressed);
            // The action taken is the chart's for this state and key (none for a written ignore).
            REQUIRE(replay.last_action() == expected);
            if (!expected) {
                // Only a written ignore does nothing.
                REQUIRE(std::any_of(replay_ignores().begin(), replay_ignores().end(), [&](const ReplayIgnore& ignore) {
                    return ignore.state == way.state && ignore.key == key;
                }));
                REQUIRE(Seen::of(replay).handled == before.handled);
                continue;
            }
            INFO("row: " << replay_action_name(*expected));
            check_effect(*expected, pressed, before, Seen::of(replay), facts.typing);
        }
    REQUIRE(states_walked.size() == replay_state_count);
}

TEST_CASE("comma and period pause a paced lesson's animation and step one frame a press, the caption kept: Space resumes it, "
          "and after its end Space is the next step again",
          "[lesson][replay][deck]")
{
    // The class plan's surface lesson, PgDn to the animation, as a teacher drives it (issue 55: the
    // first . paused and stepped once, every later , or . only showed the hint badge, and Space then
    // used up the script's overlay step).
    const KeyScript script = read_script(data_folder / "n-to-l" / "lesson-surface.keys");
    Deck deck(script, "n-to-l", on_space, Animations::stop_at);
    while (deck.replay->state() != ReplayState::animation_playing && deck.replay->playing())
        deck.press(KeyEvent::of(Key::page_down));
    REQUIRE(deck.replay->state() == ReplayState::animation_playing);
    const std::string caption = deck.replay->screen().caption;
    const std::string place = deck.replay->screen().badge_place;
    const std::size_t handled = deck.replay->handled().size();
    REQUIRE(message_line(*deck.replay).starts_with("KEY1: key1.dat"));
    for (int frame = 1; frame <= 5; ++frame) {
        deck.press(KeyEvent::typed(U'.'));
        INFO("press " << frame);
        REQUIRE(deck.replay->state() == ReplayState::animation_paused);
        REQUIRE(message_line(*deck.replay).starts_with("In-between " + std::to_string(frame) + " of 12"));
        REQUIRE(message_line(*deck.replay).ends_with("(paused)"));
        REQUIRE(deck.replay->screen().caption == caption);
        REQUIRE(deck.replay->screen().badge_place == place);
    }
    deck.press(KeyEvent::typed(U','));
    REQUIRE(message_line(*deck.replay).starts_with("In-between 4 of 12"));
    // Five frame keys and , reached the session, nothing of the script.
    REQUIRE(deck.replay->handled().size() == handled + 6);
    deck.press(KeyEvent::of(Key::space));
    REQUIRE(deck.replay->state() == ReplayState::animation_playing);
    play_to_idle(*deck.replay); // the clock: the frames to their end
    REQUIRE(deck.replay->state() == ReplayState::waiting_for_space);
    REQUIRE(message_line(*deck.replay) == "Press any key to see all frames");
    REQUIRE(deck.replay->screen().caption == caption);
    const std::size_t before_overlay = deck.replay->handled().size();
    deck.press(KeyEvent::of(Key::space));
    REQUIRE(deck.replay->handled().size() == before_overlay + 1);
    // The overlay's key is the last caption's: it shows with it, beside the overlay (SPEC 3.2).
    REQUIRE(deck.replay->screen().caption == script.captions.back().text);
}
