// The slide-deck keys of a paced replay (SPEC §3.1): START, PgDn, PgUp, Home, the caption count,
// Esc, the end of the script and a skipped goal, driven headless as a terminal would drive them.
#include "apcs/lesson/replay_driver.h"
#include "apcs/screens/replay_caption.h"
#include "apcs/session/rewindable_files.h"

#include "support/replay_deck.h"
#include "support/replay_support.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

using namespace apcs;
using test::Deck;
using test::data_folder;
using test::example_files;
using test::at_goal_feedback;
using test::message_line;

namespace {

void press(ReplayDriver& replay, KeyEvent key)
{
    replay.handle(key);
    play_to_idle(replay);
}

CellGrid cells_of(const ProgramScreen& screen)
{
    return screen.graphics ? render_cells(screen.picture, {80, 24}, GlyphSet::ascii) : screen.text;
}

const KeyEvent space = KeyEvent::of(Key::space);
const KeyEvent page_down = KeyEvent::of(Key::page_down);
const KeyEvent page_up = KeyEvent::of(Key::page_up);
const KeyEvent home = KeyEvent::of(Key::home);

// The N to L example's opening answers, up to the path screen where the decks begin.
const std::string n_to_l_opening = "ENTER ENTER\n"
                                   "TEXT 0 90 100\n"
                                   "ENTER\n"
                                   "TEXT ani1.dat\n"
                                   "ENTER ENTER\n"
                                   "START\n";

const std::string n_to_l_deck = n_to_l_opening +
                                ";; one\n"
                                "8\n"
                                ";; two\n"
                                "6 6 6\n"
                                ";; three\n"
                                "4\n";

} // namespace

TEST_CASE("START ends the preamble: its keys are one step, named START, and it stands alone once before the "
          "first caption and goal",
          "[lesson][replay][keys]")
{
    const KeyScript script = test::parsed_deck("ENTER ENTER\nTEXT 0 90\nSTART ; the lesson begins\n;; one\n8\n");
    REQUIRE(script.preamble_end == 6);
    REQUIRE(step_length(script, 0) == 6);
    REQUIRE(step_length(script, 2) == 4);
    REQUIRE(step_label(script, 0) == "START");
    REQUIRE(step_length(script, 6) == 1);
    REQUIRE(step_label(script, 6) == "8");
    REQUIRE(test::parsed_deck("ENTER\n;; one\n8\n").preamble_end == 0);
    // The keys-only reader takes it too (a recording that keeps it replays).
    REQUIRE(parse_key_script("ENTER\nSTART\n8\n", "k.keys")->size() == 2);
    const auto refused = [](const std::string& text) {
        const Expected<KeyScript> refusal = parse_captioned_key_script(text, "deck.keys");
        REQUIRE_FALSE(refusal);
        return refusal.error().to_string();
    };
    REQUIRE(refused("ENTER\nSTART\n8\nSTART\n") ==
            "deck.keys:4: a second START (the first is on line 2); expected one START line, alone, before the first "
            "caption and GOAL (the keys before it play as one step)");
    REQUIRE(refused("ENTER\n;; one\nSTART\n").starts_with("deck.keys:3: START after a caption or GOAL; expected"));
    REQUIRE(refused("ENTER\nGOAL VALUE TENSION 0.40 0.60\nSTART\n").starts_with("deck.keys:3: START after a caption"));
    REQUIRE(refused("ENTER START\n").starts_with("deck.keys:1: START shares its line with keys; expected"));
    // In a TEXT line START is typed text.
    REQUIRE(test::parsed_deck("TEXT START\n").events.size() == 5);
}

TEST_CASE("a paced lesson begins after its preamble with no caption yet, the badge saying START and caption 0 of "
          "N, and the first PgDn shows caption 1 with its keys played (SPEC 3.2)",
          "[lesson][replay][deck]")
{
    const KeyScript script = test::parsed_deck(n_to_l_deck);
    REQUIRE(script.preamble_end == 21);
    Deck deck(script, "n-to-l");
    REQUIRE(deck.replay->handled().size() == 21);
    const ProgramScreen shown = deck.replay->screen();
    REQUIRE(shown.graphics);
    REQUIRE(shown.caption.empty());
    REQUIRE(shown.badge == "START");
    REQUIRE(shown.badge_place == "caption 0 of 3");
    REQUIRE(with_played_key(CellGrid(80, 24), shown.badge, shown.badge_place).row_text(0).ends_with(
        " key START | caption 0 of 3   "));
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->handled().size() == 22);
    const ProgramScreen first = deck.replay->screen();
    REQUIRE(first.caption == "one");
    REQUIRE(first.badge_place == "caption 1 of 3");
    REQUIRE(cells_of(with_caption(first, first.caption)).row_text(23).starts_with(" one"));
    // A lesson with no START opens on its first prompt, nothing played: the place stands alone.
    const KeyScript no_start = test::parsed_deck(";; one\nENTER\n;; two\nENTER\n");
    Deck opening(no_start, "n-to-l");
    REQUIRE(opening.replay->handled().empty());
    REQUIRE(opening.replay->screen().badge.empty());
    REQUIRE(opening.replay->screen().badge_place == "caption 0 of 2");
    REQUIRE(with_played_key(CellGrid(80, 24), "", "caption 0 of 2").row_text(0).ends_with(" caption 0 of 2   "));
}

TEST_CASE("a key a paced replay does not take puts in the badge the keys it does, until the next key",
          "[lesson][replay][deck]")
{
    // A student at the first screen pressed 8, as the 8/2 choice on the message line invites, and
    // nothing happened, nothing said why.
    const KeyScript script = test::parsed_deck(n_to_l_deck);
    Deck deck(script, "n-to-l");
    press(*deck.replay, KeyEvent::typed(U'8'));
    REQUIRE(deck.replay->handled().size() == 21); // not played: the keys are the script's
    const ProgramScreen told = deck.replay->screen();
    REQUIRE(told.badge_place == replay_keys_on_space);
    REQUIRE(with_played_key(CellGrid(80, 24), told.badge, told.badge_place).row_text(0).ends_with(
        " key START | Space next step  PgDn next caption  Esc your keyboard   "));
    press(*deck.replay, space);
    REQUIRE(deck.replay->handled().size() == 22);
    REQUIRE(deck.replay->screen().badge_place == "caption 1 of 3"); // shown with its first key
    // A long step's label gives way to the keys: the badge still fits the 80-column top edge.
    const KeyScript long_step = test::parsed_deck(n_to_l_opening + ";; one\nTEXT my-first-path.dat\n;; two\n8\n");
    Deck typed(long_step, "n-to-l"); // the replay keeps a reference to its script
    press(*typed.replay, space);
    press(*typed.replay, KeyEvent::typed(U'x'));
    const ProgramScreen long_label = typed.replay->screen();
    REQUIRE(long_label.badge == "TEXT my-f...");
    REQUIRE(with_played_key(CellGrid(80, 24), long_label.badge, long_label.badge_place).row_text(0).ends_with(
        " key TEXT my-f... | Space next step  PgDn next caption  Esc your keyboard   "));
}

TEST_CASE("PgDn shows the next caption and plays its keys, stopping before the caption after it, and past the last it "
          "tells the end",
          "[lesson][replay][deck]")
{
    const KeyScript script = test::parsed_deck(n_to_l_deck);
    Deck deck(script, "n-to-l");
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->handled().size() == script.captions[1].before_event);
    REQUIRE(deck.replay->screen().caption == "one");
    REQUIRE(deck.replay->screen().badge == "PGDN");
    REQUIRE(deck.replay->screen().badge_place == "caption 1 of 3");
    // ']' is PgDn while the replay waits for the presenter.
    press(*deck.replay, KeyEvent::typed(U']'));
    REQUIRE(deck.replay->handled().size() == script.captions[2].before_event);
    REQUIRE(deck.replay->screen().caption == "two");
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->handled() == script.events);
    REQUIRE(deck.replay->screen().caption == "three");
    REQUIRE(deck.replay->state() == ReplayState::end);
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->screen().caption == end_of_script_caption);
    // Past the end nothing more is played, and PgDn types nothing into the session.
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->handled() == script.events);
    REQUIRE(deck.told == std::vector<std::size_t>{0, 1, 2});
}

TEST_CASE("Space after the script's last step tells the end on the caption row", "[lesson][replay][deck]")
{
    const KeyScript script = test::parsed_deck(n_to_l_deck);
    Deck deck(script, "n-to-l");
    for (int step = 0; step < 5; ++step)
        press(*deck.replay, space);
    REQUIRE(deck.replay->handled() == script.events);
    REQUIRE(deck.replay->screen().caption == "three");
    press(*deck.replay, space);
    REQUIRE(deck.replay->screen().caption == end_of_script_caption);
    REQUIRE(deck.replay->handled() == script.events);
}

TEST_CASE("PgUp and Home go back to a caption's screen, replayed in memory from the inputs as they were, writing "
          "and logging nothing",
          "[lesson][replay][deck]")
{
    // lesson.keys rewrites ani1.dat near its end: going back must still show the path as it was.
    Expected<KeyScript> lesson = parse_captioned_key_script(test::read_all(data_folder / "n-to-l" / "lesson.keys"), "lesson.keys");
    REQUIRE(lesson);
    Deck deck(*lesson, "n-to-l");
    const CellGrid start = cells_of(deck.replay->screen());
    std::vector<CellGrid> first_seen;
    for (std::size_t caption = 0; caption < lesson->captions.size(); ++caption) {
        press(*deck.replay, page_down);
        first_seen.push_back(cells_of(deck.replay->screen()));
        REQUIRE(deck.replay->screen().caption == lesson->captions[caption].text);
    }
    REQUIRE(deck.replay->handled() == lesson->events);
    press(*deck.replay, page_down);
    const std::string ani1_rewritten = deck.folder.files.at("ani1.dat");
    const std::size_t writes = deck.folder.writes.size();
    const std::size_t log_lines = deck.folder.log_lines.size();
    REQUIRE(writes > 0);
    // The last caption has no keys: a PgDn of its own showed it, the next told the end, and PgUp
    // from there goes to the last caption's screen (SPEC 3.2), then back one a press.
    REQUIRE(deck.replay->screen().caption == end_of_script_caption);
    for (std::size_t caption = lesson->captions.size(); caption-- > 0;) {
        press(*deck.replay, page_up);
        INFO("back to caption " << caption + 1 << ": " << lesson->captions[caption].text);
        REQUIRE(deck.replay->screen().caption == lesson->captions[caption].text);
        REQUIRE(deck.replay->screen().badge == "PGUP");
        REQUIRE(deck.replay->screen().badge_place ==
                "caption " + std::to_string(caption + 1) + " of " + std::to_string(lesson->captions.size()));
        REQUIRE(cells_of(deck.replay->screen()) == first_seen[caption]);
        const std::size_t keys_end = caption + 1 < lesson->captions.size() ? lesson->captions[caption + 1].before_event
                                                                            : lesson->events.size();
        REQUIRE(deck.replay->handled().size() == keys_end);
    }
    REQUIRE(deck.folder.writes.size() == writes);
    REQUIRE(deck.folder.log_lines.size() == log_lines);
    REQUIRE(deck.folder.files.at("ani1.dat") == ani1_rewritten);
    // PgUp at the first caption goes to the start, no caption shown; Home from anywhere to caption 1.
    press(*deck.replay, page_up);
    REQUIRE(cells_of(deck.replay->screen()) == start);
    REQUIRE(deck.replay->screen().caption.empty());
    REQUIRE(deck.replay->screen().badge_place == "caption 0 of " + std::to_string(lesson->captions.size()));
    REQUIRE(deck.replay->handled().size() == lesson->preamble_end);
    press(*deck.replay, page_down);
    press(*deck.replay, page_down);
    press(*deck.replay, home);
    REQUIRE(deck.replay->screen().badge == "HOME");
    REQUIRE(deck.replay->screen().caption == lesson->captions[0].text);
    REQUIRE(cells_of(deck.replay->screen()) == first_seen[0]);
    // Gone back, the replay goes forward for real again: the same captions, each told once.
    for (std::size_t caption = 1; caption < lesson->captions.size(); ++caption)
        press(*deck.replay, page_down);
    REQUIRE(deck.replay->handled() == lesson->events);
    REQUIRE(deck.folder.writes.size() > writes);
    REQUIRE(deck.told.size() == lesson->captions.size());
}

TEST_CASE("Esc hands the keyboard over and keeps the caption on the row, not the script's last, and PgUp, PgDn and Home "
          "give it back to the lesson (SPEC 3.2)",
          "[lesson][replay][deck]")
{
    const KeyScript script = test::parsed_deck(n_to_l_deck);
    Deck deck(script, "n-to-l");
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->screen().caption == "one");
    const CellGrid at_one = cells_of(deck.replay->screen());
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->screen().caption == "two");
    const CellGrid at_two = cells_of(deck.replay->screen());
    press(*deck.replay, KeyEvent::of(Key::escape));
    REQUIRE_FALSE(deck.replay->playing());
    REQUIRE(deck.replay->state() == ReplayState::keyboard);
    REQUIRE(deck.replay->screen().caption == "two");
    REQUIRE(deck.replay->screen().badge_place == replay_keys_keyboard);
    REQUIRE(with_played_key(CellGrid(80, 24), deck.replay->screen().badge, deck.replay->screen().badge_place)
                .row_text(0)
                .ends_with(" key ESC | your keyboard: PgUp/PgDn/Home return   "));
    // The presenter's keys are the session's; the caption goes (it is no longer true of the screen),
    // the badge stays.
    const std::size_t handled = deck.replay->handled().size();
    press(*deck.replay, KeyEvent::typed(U'6'));
    press(*deck.replay, KeyEvent::typed(U'6'));
    REQUIRE(deck.replay->handled().size() == handled + 2);
    REQUIRE(deck.replay->screen().caption.empty());
    REQUIRE(deck.replay->screen().badge_place == replay_keys_keyboard);
    // PgUp: caption two's screen again, the presenter's keys undone; PgUp again: caption one.
    press(*deck.replay, page_up);
    REQUIRE(deck.replay->screen().caption == "two");
    REQUIRE(deck.replay->screen().badge == "PGUP");
    REQUIRE(deck.replay->screen().badge_place == "caption 2 of 3");
    REQUIRE(cells_of(deck.replay->screen()) == at_two);
    REQUIRE(deck.replay->handled().size() == script.captions[2].before_event);
    press(*deck.replay, page_up);
    REQUIRE(deck.replay->screen().caption == "one");
    REQUIRE(cells_of(deck.replay->screen()) == at_one);
    // Esc, a key, PgDn: the next caption's screen; Esc, a key, Home: the first.
    press(*deck.replay, KeyEvent::of(Key::escape));
    press(*deck.replay, KeyEvent::typed(U'8'));
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->screen().caption == "two");
    REQUIRE(deck.replay->screen().badge == "PGDN");
    REQUIRE(cells_of(deck.replay->screen()) == at_two);
    REQUIRE(deck.replay->playing());
    press(*deck.replay, KeyEvent::of(Key::escape));
    press(*deck.replay, KeyEvent::typed(U'6'));
    press(*deck.replay, home);
    REQUIRE(deck.replay->screen().caption == "one");
    REQUIRE(deck.replay->screen().badge == "HOME");
    REQUIRE(cells_of(deck.replay->screen()) == at_one);
}

TEST_CASE("PgUp at End of the script goes to the last caption's screen, caption N of N", "[lesson][replay][deck]")
{
    const KeyScript script = test::parsed_deck(n_to_l_deck);
    Deck deck(script, "n-to-l");
    press(*deck.replay, page_down);
    press(*deck.replay, page_down);
    press(*deck.replay, page_down);
    const CellGrid at_three = cells_of(deck.replay->screen());
    REQUIRE(deck.replay->screen().caption == "three");
    REQUIRE(deck.replay->state() == ReplayState::end);
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->screen().caption == end_of_script_caption);
    press(*deck.replay, page_up);
    REQUIRE(deck.replay->screen().caption == "three");
    REQUIRE(deck.replay->screen().badge_place == "caption 3 of 3");
    REQUIRE(cells_of(deck.replay->screen()) == at_three);
    // From the end not yet told (caption 3 on the row, its keys played) PgUp is back a caption.
    REQUIRE(deck.replay->state() == ReplayState::end);
    press(*deck.replay, page_up);
    REQUIRE(deck.replay->screen().badge_place == "caption 2 of 3");
}

TEST_CASE("PgDn at a goal skips it: apcs.log says goal skipped, its answer is not played and the closing caption "
          "shows - at a goal the key of a right bracket is the session's",
          "[lesson][replay][deck][goal]")
{
    Expected<KeyScript> exercise = parse_captioned_key_script(
        test::read_all(data_folder / "exercises" / "exercise-1-tension.keys"), "exercise-1-tension.keys");
    REQUIRE(exercise);
    Deck deck(*exercise, "exercises");
    for (int step = 0; step < 40 && !at_goal_feedback(*deck.replay); ++step)
        press(*deck.replay, space);
    REQUIRE(at_goal_feedback(*deck.replay));
    const std::size_t at_goal = deck.replay->handled().size();
    press(*deck.replay, KeyEvent::typed(U']'));
    REQUIRE(deck.replay->handled().size() == at_goal + 1);
    REQUIRE(at_goal_feedback(*deck.replay));
    press(*deck.replay, page_down);
    REQUIRE(deck.folder.log_lines.back() == "goal skipped");
    REQUIRE(deck.replay->handled().size() == at_goal + 1);
    // Nothing on screen says the goal was reached (SPEC 3.2): how far it was, and the closing
    // caption marked; both until the next key, the caption for as long as it is on the row.
    REQUIRE(message_line(*deck.replay) == "GOAL skipped: tension +0.00, want +0.40 to +0.60");
    REQUIRE(deck.replay->screen().caption == "(skipped) " + exercise->captions.back().text);
    press(*deck.replay, KeyEvent::typed(U'x'));
    REQUIRE_FALSE(message_line(*deck.replay).starts_with("GOAL"));
}

TEST_CASE("after PgUp the recording is the script up to the caption gone back to and what was typed from there "
          "and PgDn PgUp Home are never in it",
          "[lesson][replay][deck][record]")
{
    const std::string script = n_to_l_opening +
                               ";; one\n8\n;; two\nGOAL VALUE TENSION 0.4 0.6\n;; three\n4\n";
    const KeyScript keys = test::parsed_deck(script); // the replay keeps a reference to it
    Deck deck(keys, "n-to-l");
    for (int step = 0; step < 10 && !at_goal_feedback(*deck.replay); ++step)
        press(*deck.replay, space);
    REQUIRE(at_goal_feedback(*deck.replay));
    // At the goal the student types two keys, then goes back to caption one and plays on from there.
    press(*deck.replay, KeyEvent::typed(U'6'));
    press(*deck.replay, KeyEvent::typed(U'J'));
    const std::string before_back = deck.replay->recording().text();
    REQUIRE(before_back.ends_with(";; two\nGOAL VALUE TENSION 0.4 0.6\n6\nJ\n"));
    press(*deck.replay, page_up);
    REQUIRE(deck.replay->screen().caption == "one");
    const std::string gone_back = deck.replay->recording().text();
    CAPTURE(gone_back);
    REQUIRE(gone_back.starts_with("ENTER\nENTER\nTEXT 0 90 100\nENTER\nTEXT ani1.dat\nENTER\nENTER\nSTART\n;; one\n8\n"));
    REQUIRE(gone_back.find("6\nJ\n") == std::string::npos);
    REQUIRE_FALSE(at_goal_feedback(*deck.replay)); // until its task shows
    press(*deck.replay, space);                     // two, the task
    REQUIRE(at_goal_feedback(*deck.replay));
    press(*deck.replay, KeyEvent::typed(U'L'));
    press(*deck.replay, KeyEvent::typed(U'L'));
    press(*deck.replay, KeyEvent::typed(U'L'));
    // Caption three has a key of its own: it is recorded once it shows, with its key.
    const std::string opening = "ENTER\nENTER\nTEXT 0 90 100\nENTER\nTEXT ani1.dat\nENTER\nENTER\nSTART\n";
    REQUIRE(deck.replay->recording().text() == opening + ";; one\n8\n;; two\nGOAL VALUE TENSION 0.4 0.6\nL\nL\nL\n");
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->recording().text() ==
            opening + ";; one\n8\n;; two\nGOAL VALUE TENSION 0.4 0.6\nL\nL\nL\n;; three\n4\n");
}

TEST_CASE("the KEY files read are those of every session the replay played into, the one Home replaced too, so "
          "that a handout page or a recording never replaces a key file typed after going back",
          "[lesson][replay][deck][record]")
{
    const KeyScript keys = test::parsed_deck(";; one\nENTER\n;; two\nENTER\n;; three\nTEXT 0 90 100\n");
    MemoryFiles inputs = example_files("n-to-l");
    inputs.files["other1.dat"] = inputs.files.at("key1.dat");
    Deck deck(keys, std::move(inputs), ReplayPace{ReplayPace::Kind::on_space, 0}, Animations::play_through, {});
    press(*deck.replay, space); // KEY1: key1.dat, the default
    press(*deck.replay, space); // KEY2: key2.dat
    REQUIRE(deck.replay->key_files_read() == std::vector<std::string>{"key1.dat", "key2.dat"});
    // Home: caption one's screen again, KEY1 answered; PgUp: the start, its KEY1 prompt unanswered;
    // the presenter takes the keyboard (Esc) and types another name.
    press(*deck.replay, home);
    REQUIRE(deck.replay->screen().caption == "one");
    press(*deck.replay, page_up);
    REQUIRE(deck.replay->handled().empty());
    press(*deck.replay, KeyEvent::of(Key::escape));
    for (const char32_t letter : std::u32string(U"other1.dat"))
        press(*deck.replay, KeyEvent::typed(letter));
    press(*deck.replay, KeyEvent::of(Key::enter));
    REQUIRE(deck.replay->session().key_names()[0] == "other1.dat");
    // The first session read key1.dat and key2.dat; the one Home made, other1.dat.
    REQUIRE(deck.replay->key_files_read() == std::vector<std::string>{"key1.dat", "key2.dat", "other1.dat"});
}

TEST_CASE("an answer played a Space a step poses its goal when its task shows, before any key of the answer, and PgUp "
          "back to the task poses it again without playing the answer",
          "[lesson][replay][deck][goal]")
{
    // An exercise's answer (or a student's recording): the task, its GOAL line, the answer's keys.
    const std::string text = n_to_l_opening +
                             ";; one\n8\n;; two, the task\nGOAL VALUE TENSION 0.4 0.6\nL L L\n;; three\n4\n";
    const KeyScript script = test::parsed_deck(text);
    const std::size_t goal_at = script.goals[0].before_event;
    Deck deck(script, "n-to-l");
    press(*deck.replay, space); // one, with 8
    REQUIRE_FALSE(at_goal_feedback(*deck.replay));
    press(*deck.replay, space); // the task: the goal waits, L not played
    REQUIRE(at_goal_feedback(*deck.replay));
    REQUIRE(deck.replay->handled().size() == goal_at);
    REQUIRE(deck.replay->screen().caption == "two, the task");
    // Skipped, then back: the task's screen is where its keys end, at the GOAL line.
    press(*deck.replay, page_down);
    REQUIRE(deck.folder.log_lines.back() == "goal skipped");
    REQUIRE(deck.replay->screen().caption == "(skipped) three");
    press(*deck.replay, page_up);
    REQUIRE(deck.replay->screen().caption == "two, the task");
    REQUIRE(deck.replay->handled().size() == goal_at);
    REQUIRE(at_goal_feedback(*deck.replay));
}

TEST_CASE("keys typed after Esc at caption K are recorded under caption K, not under the caption after it",
          "[lesson][replay][deck][record]")
{
    const KeyScript script = test::parsed_deck(n_to_l_deck);
    Deck deck(script, "n-to-l");
    press(*deck.replay, page_down); // one, with 8
    press(*deck.replay, KeyEvent::of(Key::escape));
    press(*deck.replay, KeyEvent::typed(U'L'));
    const std::string recorded = deck.replay->recording().text();
    CAPTURE(recorded);
    REQUIRE(recorded.ends_with("START\n;; one\n8\nL\n")); // Esc is the replay's, not the session's
}

TEST_CASE("two GOAL lines under one task wait in turn: skipping the first poses the second, and the caption after "
          "them shows only when the presenter asks for it",
          "[lesson][replay][deck][goal]")
{
    const std::string text = n_to_l_opening + "8\n"
                             ";; the task\nGOAL VALUE TENSION 0.4 0.6\nGOAL VALUE BIAS 0.3 0.5\n;; closing\n4\n";
    const KeyScript script = test::parsed_deck(text);
    Deck deck(script, "n-to-l");
    press(*deck.replay, page_down);
    REQUIRE(message_line(*deck.replay).starts_with("GOAL: tension"));
    press(*deck.replay, page_down);
    CAPTURE(message_line(*deck.replay));
    REQUIRE(message_line(*deck.replay).find("the goal is BIAS") != std::string::npos);
    REQUIRE(deck.replay->screen().caption == "the task");
    const std::size_t at_second = deck.replay->handled().size();
    REQUIRE(at_second == script.goals[1].before_event);
    // The second reached: the closing caption has a key of its own, so it waits for PgDn (it had
    // been counted shown by the first skip, and its key played unasked).
    for (const KeyEvent key : {KeyEvent::of(Key::enter), KeyEvent::of(Key::enter), KeyEvent::typed(U'L'),
                               KeyEvent::typed(U'L')})
        press(*deck.replay, key);
    REQUIRE(message_line(*deck.replay).starts_with("GOAL REACHED: bias"));
    REQUIRE(deck.replay->handled().size() == at_second + 4);
    REQUIRE(deck.replay->screen().caption == "the task");
    // It closes the tension goal too, which was skipped: it says so.
    press(*deck.replay, page_down);
    REQUIRE(deck.replay->screen().caption == "(skipped) closing");
    REQUIRE(deck.replay->handled().size() == at_second + 5);
}
