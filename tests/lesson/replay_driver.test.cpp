// The one replay driver, headless: a paced, captioned lesson and an exercise with its goal played
// as a terminal would play them (Space for each step, the clock, the student's keys), without one.
#include "apcs/lesson/replay_driver.h"
#include "apcs/screens/replay_caption.h"
#include "apcs/session/session_files.h"

#include "support/replay_support.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace apcs;
using test::data_folder;
using test::example_files;
using test::at_goal_feedback;
using test::message_line;
using test::read_script;

namespace {

// The steps of `script` as a paced replay plays them: a TEXT line is one.
std::size_t step_count(const KeyScript& script)
{
    std::size_t steps = 0;
    for (std::size_t first = 0; first < script.events.size(); first += step_length(script, first))
        ++steps;
    return steps;
}

const KeyEvent space = KeyEvent::of(Key::space);

// A screen as 80x24 cells, graphics or text.
CellGrid cells_of(const ProgramScreen& screen)
{
    return screen.graphics ? render_cells(screen.picture, {80, 24}, GlyphSet::ascii) : screen.text;
}

std::string rows_of(const CellGrid& grid)
{
    std::string rows;
    for (int row = 0; row < grid.rows(); ++row)
        rows += grid.row_text(row) + "\n";
    return rows;
}

struct CaptionSeen {
    std::size_t index = 0;
    std::string caption_row;
};

} // namespace

TEST_CASE("lesson-continuity.keys paced a step per Space: every step once, each caption told over the screen it captions, "
          "the badge naming the step",
          "[lesson][replay]")
{
    const KeyScript script = read_script(data_folder / "n-to-l" / "lesson-continuity.keys");
    REQUIRE(script.captions.size() > 5);
    MemoryFiles files = example_files("n-to-l");
    Session session({}, files);
    std::vector<std::size_t> told;
    ReplayHooks hooks;
    hooks.caption_reached = [&](std::size_t index, const ProgramScreen& shown) {
        told.push_back(index);
        // The screen handed over is the session's with the caption laid on its caption row.
        const CellGrid cells = cells_of(shown);
        REQUIRE(cells == cells_of(with_caption(session.screen(), script.captions[index].text)));
        REQUIRE(cells.row_text(23).starts_with(" " + script.captions[index].text));
    };
    ReplayDriver replay(session, script, "lesson-continuity.keys", {ReplayPace::Kind::on_space, 0}, hooks,
                        ReplayAudience::terminal);
    std::size_t spaces = 0;
    std::size_t captions_shown = 0;
    while (replay.state() != ReplayState::end && !replay.finished()) {
        play_to_idle(replay);
        if (replay.state() == ReplayState::end)
            break;
        // A key other than Space is swallowed while the replay waits: nothing is played, and the
        // badge names the keys the replay takes.
        const std::size_t handled = replay.handled().size();
        replay.handle(KeyEvent::typed(U'x'));
        REQUIRE(replay.handled().size() == handled);
        REQUIRE(replay.screen().badge_place == replay_keys_on_space);
        const std::uint64_t revision = replay.screen_revision();
        const std::size_t played = replay.handled().size();
        replay.handle(space);
        ++spaces;
        play_to_idle(replay);
        REQUIRE(replay.screen_revision() > revision);
        // The caption of the step just played, shown with its first key (SPEC 3.2); a caption with
        // no keys, by a Space of its own.
        if (replay.handled().size() == played) {
            ++captions_shown;
            REQUIRE(replay.screen().badge.empty());
        } else {
            captions_shown = static_cast<std::size_t>(
                std::count_if(script.captions.begin(), script.captions.end(),
                              [&](const ScriptCaption& caption) { return caption.before_event <= played; }));
            REQUIRE_FALSE(replay.screen().badge.empty());
        }
        REQUIRE(captions_shown > 0);
        REQUIRE(replay.screen().caption == script.captions[captions_shown - 1].text);
    }
    // Space by Space, the script's steps, no more and no fewer, and each caption without keys,
    // and every key of it handled; the preamble (the keys before START) played as the replay
    // began, with no Space.
    REQUIRE(script.preamble_end > 0);
    REQUIRE(captions_shown == script.captions.size());
    const auto keyless = std::count_if(script.captions.begin(), script.captions.end(), [&](const ScriptCaption& caption) {
        const std::size_t index = static_cast<std::size_t>(&caption - script.captions.data());
        const std::size_t end =
            index + 1 < script.captions.size() ? script.captions[index + 1].before_event : script.events.size();
        return end == caption.before_event;
    });
    REQUIRE(keyless > 0);
    REQUIRE(spaces == step_count(script) - 1 + static_cast<std::size_t>(keyless));
    REQUIRE(replay.handled() == script.events);
    std::vector<std::size_t> every_caption(script.captions.size());
    for (std::size_t k = 0; k < every_caption.size(); ++k)
        every_caption[k] = k;
    REQUIRE(told == every_caption);
}

TEST_CASE("a paced replay shows the screens the headless replay prints, caption by caption", "[lesson][replay]")
{
    const KeyScript script = read_script(data_folder / "n-to-l" / "lesson.keys");
    const auto caption_screens = [&](ReplayAudience audience) {
        MemoryFiles files = example_files("n-to-l");
        Session session({}, files);
        std::vector<CellGrid> screens;
        ReplayHooks hooks;
        hooks.caption_reached = [&](std::size_t, const ProgramScreen& shown) {
            screens.push_back(cells_of(shown));
        };
        ReplayDriver replay(session, script, "lesson.keys", {ReplayPace::Kind::every, 100}, hooks, audience);
        if (audience == ReplayAudience::headless) {
            play_to_idle(replay);
            replay.finish();
        } else {
            // One step every 100 ms: the clock's ticks alone play it.
            while (replay.playing() && !replay.finished()) {
                REQUIRE((replay.busy() || replay.animating()));
                if (!replay.busy() && !session.animating())
                    REQUIRE(replay.delay_ms() == 100);
                play_to_idle(replay);
            }
        }
        return screens;
    };
    const std::vector<CellGrid> paced = caption_screens(ReplayAudience::terminal);
    REQUIRE(paced.size() == script.captions.size());
    const std::vector<CellGrid> headless = caption_screens(ReplayAudience::headless);
    REQUIRE(headless.size() == paced.size());
    for (std::size_t k = 0; k < paced.size(); ++k) {
        INFO("caption " << k + 1 << ": " << script.captions[k].text);
        REQUIRE(rows_of(paced[k]) == rows_of(headless[k]));
    }
}

TEST_CASE("Esc hands the keyboard over: the script stops, the caption stays until a key is typed, the badge says so",
          "[lesson][replay]")
{
    const KeyScript script = read_script(data_folder / "n-to-l" / "lesson.keys");
    MemoryFiles files = example_files("n-to-l");
    Session session({}, files);
    ReplayDriver replay(session, script, "lesson.keys", {ReplayPace::Kind::on_space, 0}, {}, ReplayAudience::terminal);
    for (int step = 0; step < 6; ++step) {
        replay.handle(space);
        play_to_idle(replay);
    }
    const std::vector<KeyEvent> played = replay.handled();
    REQUIRE_FALSE(replay.screen().caption.empty());
    replay.handle(KeyEvent::of(Key::escape));
    REQUIRE_FALSE(replay.playing());
    REQUIRE(replay.handled() == played);
    REQUIRE_FALSE(replay.screen().caption.empty());
    REQUIRE_FALSE(replay.screen().badge.empty());
    // The keyboard's now: the key goes to the session, and the caption goes (it would no longer be
    // true of the screen); the badge says how to give the keyboard back (SPEC 3.2).
    replay.handle(KeyEvent::typed(U'6'));
    REQUIRE(replay.handled().size() == played.size() + 1);
    REQUIRE(replay.screen().caption.empty());
    REQUIRE(replay.screen().badge == "ESC");
    REQUIRE(replay.screen().badge_place == replay_keys_keyboard);
}

TEST_CASE("an exercise on a terminal waits at its goal for the student's keys, then goes on, and headless its answer "
          "passes and the exercise alone fails with FILE:LINE",
          "[lesson][replay][goal]")
{
    const std::filesystem::path exercise = data_folder / "exercises" / "exercise-1-tension.keys";
    const KeyScript script = read_script(exercise);
    REQUIRE(script.goals.size() == 1);
    SECTION("paced on a terminal")
    {
        MemoryFiles files = example_files("exercises");
        Session session({}, files);
        ReplayDriver replay(session, script, exercise.string(), {ReplayPace::Kind::on_space, 0}, {},
                            ReplayAudience::terminal);
        for (std::size_t step = 0; step < 20 && !at_goal_feedback(replay); ++step) {
            replay.handle(space);
            play_to_idle(replay);
        }
        REQUIRE(at_goal_feedback(replay));
        // The task stays on the caption row, the feedback under it on the message line.
        REQUIRE(replay.screen().caption == "Exercise 1: tighten the whole path: TENSION from +0.40 to +0.60");
        REQUIRE(message_line(replay) == "GOAL: tension +0.00, want +0.40 to +0.60");
        REQUIRE(replay.handled().size() == script.goals[0].before_event);
        // At the goal every key is the student's: L (Shift-L) raises the tension, until the goal holds.
        const double start = session.path_editor()->region_staff()->tension;
        int raised = 0;
        for (; raised < 10 && at_goal_feedback(replay); ++raised)
            replay.handle(KeyEvent::typed(U'L'));
        REQUIRE(message_line(replay) == "GOAL REACHED: tension +0.45 (want +0.40 to +0.60)");
        REQUIRE(replay.handled().size() == script.goals[0].before_event + static_cast<std::size_t>(raised));
        const double tension = session.path_editor()->region_staff()->tension;
        REQUIRE(tension > start);
        REQUIRE((tension >= 0.40 && tension <= 0.60));
        // The answer's keys are skipped: the exercise's keys end with them, and its closing
        // caption, which has no keys, shows beside the path the student made.
        REQUIRE(script.goals[0].answer_end == script.events.size());
        REQUIRE_FALSE(replay.playing());
        REQUIRE(replay.screen().caption == script.captions.back().text);
        // Until the next key.
        replay.handle(KeyEvent::typed(U'4'));
        REQUIRE_FALSE(message_line(replay).starts_with("GOAL"));
    }
    SECTION("headless")
    {
        const auto judged = [](const std::filesystem::path& file) {
            const KeyScript keys = read_script(file);
            MemoryFiles files = example_files("exercises");
            Session session({}, files);
            ReplayDriver replay(session, keys, file.string(), {}, {}, ReplayAudience::headless);
            play_to_idle(replay);
            replay.finish();
            return replay.goals();
        };
        REQUIRE(judged(data_folder / "exercises" / "answers" / "exercise-1-tension-answer.keys"));
        const Expected<void> failed = judged(exercise);
        REQUIRE_FALSE(failed);
        REQUIRE(failed.error().to_string().starts_with(exercise.string() + ":" + std::to_string(script.goals[0].line_number) +
                                               ": goal not reached: "));
    }
}

TEST_CASE("q at a goal asks to leave the exercise: N goes back to the goal, Y ends the replay and hands the keyboard over",
          "[lesson][replay][goal]")
{
    // Issue 45: at a goal every key was the student's, q included, so a goal the student could not
    // reach trapped the class (only Ctrl-C left).
    const std::filesystem::path exercise = data_folder / "exercises" / "exercise-1-tension.keys";
    const KeyScript script = read_script(exercise);
    MemoryFiles files = example_files("exercises");
    Session session({}, files);
    ReplayDriver replay(session, script, exercise.string(), {ReplayPace::Kind::on_space, 0}, {}, ReplayAudience::terminal);
    for (std::size_t step = 0; step < 20 && !at_goal_feedback(replay); ++step) {
        replay.handle(space);
        play_to_idle(replay);
    }
    const std::string goal_row = replay.screen().caption;
    REQUIRE(at_goal_feedback(replay));
    const std::size_t handled = replay.handled().size();
    const std::uint64_t revision = replay.screen_revision();
    replay.handle(KeyEvent::typed(U'q'));
    REQUIRE(replay.screen().caption == leave_exercise_question);
    REQUIRE(replay.screen_revision() != revision);
    replay.handle(KeyEvent::typed(U'n'));
    REQUIRE(replay.screen().caption == goal_row);
    REQUIRE(replay.handled().size() == handled); // neither q nor n reached the session
    replay.handle(KeyEvent::typed(U'Q'));
    replay.handle(KeyEvent::typed(U'Y'));
    REQUIRE_FALSE(replay.playing());
    REQUIRE(replay.screen().caption.empty());
    REQUIRE_FALSE(message_line(replay).starts_with("GOAL"));
    REQUIRE(replay.handled().size() == handled);
    // The keyboard is the student's: the next key reaches the session.
    replay.handle(KeyEvent::typed(U'L'));
    REQUIRE(replay.handled().size() == handled + 1);
}

TEST_CASE("q at a goal is a typed letter where the session takes text: the prompt's line, not the leave question",
          "[lesson][replay][goal]")
{
    // The review of issue 45's change: "quad.dat" typed at a prompt during a goal lost its q and u.
    const Expected<KeyScript> script = parse_captioned_key_script("GOAL VALUE TENSION 0.4 0.6\nENTER\n", "g.keys");
    REQUIRE(script);
    MemoryFiles files = example_files("exercises");
    Session session({}, files);
    ReplayDriver replay(session, *script, "g.keys", {ReplayPace::Kind::on_space, 0}, {}, ReplayAudience::terminal);
    REQUIRE(at_goal_feedback(replay));
    REQUIRE(session.takes_typed_text());
    replay.handle(KeyEvent::typed(U'q'));
    replay.handle(KeyEvent::typed(U'u'));
    REQUIRE(at_goal_feedback(replay));
    REQUIRE(replay.handled() == std::vector<KeyEvent>{KeyEvent::typed(U'q'), KeyEvent::typed(U'u')});
}

TEST_CASE("keys typed while a replay plays at once are the session's once it has played", "[lesson][replay]")
{
    KeyScript script;
    script.events = {KeyEvent::of(Key::enter), KeyEvent::of(Key::enter)};
    MemoryFiles files = example_files("n-to-l");
    Session session({}, files);
    ReplayDriver replay(session, script, "two.keys", {}, {}, ReplayAudience::terminal);
    REQUIRE(replay.busy());
    replay.handle(KeyEvent::typed(U'0'));
    REQUIRE(replay.handled().empty());
    play_to_idle(replay);
    REQUIRE_FALSE(replay.playing());
    REQUIRE(replay.handled() ==
            std::vector<KeyEvent>{KeyEvent::of(Key::enter), KeyEvent::of(Key::enter), KeyEvent::typed(U'0')});
}

TEST_CASE("the terminal paints a screen only when its revision changes: once per staff key that changes the path, "
          "never for a key that changes nothing",
          "[lesson][replay][paint]")
{
    MemoryFiles files = example_files("n-to-l");
    Session session({}, files);
    const KeyScript none;
    ReplayDriver replay(session, none, "typed", {}, {}, ReplayAudience::terminal);
    const auto type = [&](std::u32string_view keys) {
        for (const char32_t key : keys)
            replay.handle(key == U'\n' ? KeyEvent::of(Key::enter) : key == U' ' ? space : KeyEvent::typed(key));
        play_to_idle(replay);
    };
    type(U"\n\n0 90 100\nway1.dat\n\n8");
    REQUIRE(session.leaf_name() == "staff");
    const auto paints_of = [&](char32_t key) {
        const std::uint64_t before = replay.screen_revision();
        replay.handle(KeyEvent::typed(key));
        play_to_idle(replay);
        return replay.screen_revision() - before;
    };
    // Up the TENSION line to +1: every key moves the curve, and is one paint.
    while (session.path_editor()->region_staff()->tension < 1.0) {
        const std::uint64_t document = session.path_editor()->document().revision();
        REQUIRE(paints_of(U'6') == 1);
        REQUIRE(session.path_editor()->document().revision() == document + 1);
    }
    // Past +1 the first key still clears what the last one said ("moved up to ..."); then nothing
    // changes, and nothing is painted, however many keys follow.
    const std::uint64_t document = session.path_editor()->document().revision();
    paints_of(U'6');
    for (int key = 0; key < 5; ++key)
        REQUIRE(paints_of(U'6') == 0);
    REQUIRE(session.path_editor()->document().revision() == document);
    // A key no mode takes on the staff (Y) changes nothing either.
    REQUIRE(paints_of(U'Y') == 0);
    // Back down one step: the path changes, one paint.
    REQUIRE(paints_of(U'4') == 1);
}

// At a long path's slopes prompt the terminal's session makes the path's arrays between keys
// (Session::preparing); a paced replay still waits there for Space, and a key typed before that
// work is done is the replay's as at any prompt, not typed into the slopes' line.
TEST_CASE("a paced replay at a long path's slopes prompt waits for Space while the session prepares the path",
          "[lesson][replay]")
{
    MemoryFiles files;
    files.files["key1.dat"] = "0 0 0\n0 0 10\n0 6 0\n0 6 10\n";
    files.files["key2.dat"] = "0 0 10\n0 0 0\n0 5 0\n";
    std::string way = "0 0 0\n";
    for (int k = 1; k < 69'999; ++k)
        way += std::to_string(k % 5) + " " + std::to_string(k % 3) + " " + std::to_string(k % 10) + "\n";
    files.files["long.dat"] = way + "0 0 10\n";
    Expected<KeyScript> script =
        parse_captioned_key_script("ENTER\nENTER\nTEXT 0 90 0\nENTER\nTEXT long.dat\nENTER\n;; the slopes\nENTER\n",
                                   "long.keys");
    REQUIRE(script);
    SessionSettings settings;
    settings.refinement = Refinement::in_steps;
    Session session(settings, files);
    ReplayDriver replay(session, *script, "long.keys", {ReplayPace::Kind::on_space, 0}, {}, ReplayAudience::terminal);
    for (int step = 0; step < 10 && session.leaf_name() != "ask_slopes"; ++step) {
        play_to_idle(replay);
        replay.handle(space);
    }
    REQUIRE(session.leaf_name() == "ask_slopes");
    REQUIRE(session.preparing());
    REQUIRE(replay.state() == ReplayState::waiting_for_space);
    const std::size_t handled = replay.handled().size();
    replay.handle(KeyEvent::typed(U'x'));
    REQUIRE(replay.handled().size() == handled);
    play_to_idle(replay); // the arrays made
    REQUIRE_FALSE(session.preparing());
    replay.handle(space);
    play_to_idle(replay);
    REQUIRE(session.leaf_name() == "control_choice");
}
