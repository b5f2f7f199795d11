// Issue 43 item 3: at a goal the task's caption stays on the caption row and the goal's feedback is
// on the message line, says GOAL REACHED, names a wrong staff line or region, and says why an
// in-between did not move; apcs.log has a line per goal; --record keeps the student's keys as
// tokens between the script's GOAL line and its closing caption.
#include "apcs/lesson/goal_check.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/screens/replay_caption.h"
#include "apcs/screens/words.h"
#include "apcs/session/session_files.h"
#include "support/replay_support.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

using namespace apcs;
using test::data_folder;
using test::example_files;
using test::message_line;
using test::read_script;

namespace {

// An exercise paced a step per Space on the exercises' files in memory, played on to its goal; the
// lines it logs kept.
struct Exercise {
    KeyScript script;
    MemoryFiles files = example_files("exercises");
    Session session{{}, files};
    std::vector<std::string> logged;
    std::unique_ptr<ReplayDriver> replay;

    explicit Exercise(const std::string& name)
        : script(read_script(data_folder / "exercises" / name))
    {
        ReplayHooks hooks;
        hooks.log = [this](const std::string& line) { logged.push_back(line); };
        replay = std::make_unique<ReplayDriver>(session, script, name, ReplayPace{ReplayPace::Kind::on_space, 0}, hooks,
                                                ReplayAudience::terminal);
        for (int step = 0; step < 20 && !test::at_goal_feedback(*replay); ++step)
            press(KeyEvent::of(Key::space));
        REQUIRE(test::at_goal_feedback(*replay));
    }
    std::string press(KeyEvent key)
    {
        replay->handle(key);
        play_to_idle(*replay);
        const std::string message = message_line(*replay);
        // The message line holds 79 columns: the feedback is never cut.
        INFO(message);
        CHECK(message.size() <= 79);
        return message;
    }
    std::string press(char32_t typed) { return press(KeyEvent::typed(typed)); }
};

const KeyEvent enter = KeyEvent::of(Key::enter);

} // namespace

TEST_CASE("at a goal the task stays on the caption row and the message line names a wrong staff line until the "
          "goal is reached",
          "[lesson][replay][goal]")
{
    Exercise exercise("exercise-2-continuity.keys");
    const std::string task = "Exercise 2: a corner at the middle point: CONTINUITY from -0.60 to -0.40";
    REQUIRE(exercise.replay->screen().caption == task);
    REQUIRE(message_line(*exercise.replay) == "GOAL: continuity +0.00, want -0.60 to -0.40");
    REQUIRE(exercise.press(enter) == "GOAL: you are on BIAS; the goal is CONTINUITY: finish the staff, then Y");
    REQUIRE(exercise.press(enter) ==
            "GOAL: you are on ACCELERATION; the goal is CONTINUITY: finish the staff, then Y");
    // The question after the staff comes first on the message line (SPEC §7.3), the goal beside it
    // where both fit in 79 columns, so the student sees whether to answer Y; the task keeps the
    // caption row.
    REQUIRE(exercise.press(enter) ==
            "Adjust the path again ? (Y/N)   GOAL: continuity +0.00, want -0.60 to -0.40");
    REQUIRE(exercise.replay->screen().caption == task);
    REQUIRE(exercise.press(U'Y') == "GOAL: 8 puts the whole path on the staff, 2 a region");
    REQUIRE(exercise.press(U'8') == "GOAL: you are on TENSION; the goal is CONTINUITY: Enter or Esc goes down a line");
    REQUIRE(exercise.press(enter) == "GOAL: continuity +0.00, want -0.60 to -0.40");
    REQUIRE(exercise.press(U'J') == "GOAL: continuity -0.15, want -0.60 to -0.40");
    exercise.press(U'J');
    REQUIRE(exercise.press(U'4') == "GOAL: continuity -0.35, want -0.60 to -0.40");
    REQUIRE(exercise.press(U'4') == "GOAL REACHED: continuity -0.40 (want -0.60 to -0.40)");
    // The closing caption describes the goal reached; the next key takes GOAL REACHED away.
    REQUIRE(exercise.replay->screen().caption == exercise.script.captions.back().text);
    REQUIRE_FALSE(exercise.press(U'4').starts_with("GOAL"));
    // The goal is judged on its path as the student accepts it (SPEC 3.2), continuity -0.45 now:
    // apcs.log's line comes with the N that accepts the path.
    REQUIRE(exercise.logged.empty());
    for (int line = 0; line < 3; ++line)
        exercise.press(enter);
    exercise.press(U'N');
    REQUIRE(exercise.logged == std::vector<std::string>{"goal reached: continuity -0.45 at key " +
                                                        std::to_string(exercise.replay->handled().size())});
}

TEST_CASE("a NEAR goal names the region on the staff when no key there can move the span nearest its point",
          "[lesson][replay][goal]")
{
    Exercise exercise("exercise-4-near.keys");
    REQUIRE(message_line(*exercise.replay).starts_with("GOAL: the curve passes "));
    for (int line = 0; line < 4; ++line)
        exercise.press(enter);
    exercise.press(U'Y');
    exercise.press(U'2');
    // Local control on control point 3 alone: its values shape spans 2 to 3 and beyond, not span 1
    // to 2, where the goal's point lies.
    for (int right = 0; right < 3; ++right)
        exercise.press(U'6');
    exercise.press(enter);
    REQUIRE(exercise.press(enter) == "GOAL: the region (points 3 to 3) cannot move span 1 to 2, nearest the goal");
    // On control point 2 it can: the distance again. (A region of one point has no ACCELERATION.)
    for (int line = 0; line < 2; ++line)
        exercise.press(enter);
    // Beside the question the whole feedback does not fit in 79 columns: it is said briefly.
    REQUIRE(exercise.press(enter) == "Adjust the path again ? (Y/N)   GOAL: 0.39 off, want within 0.10");
    exercise.press(U'Y');
    exercise.press(U'2');
    exercise.press(U'6');
    exercise.press(U'6');
    exercise.press(enter);
    REQUIRE(exercise.press(enter).starts_with("GOAL: the curve passes "));
}

TEST_CASE("an INBETWEEN goal says when a staff key left its in-between where it was and why",
          "[lesson][replay][goal]")
{
    Exercise exercise("exercise-5-inbetween.keys");
    std::string before = message_line(*exercise.replay);
    int stayed = 0;
    for (int step = 0; step < 9 && !before.starts_with("GOAL REACHED"); ++step) {
        const std::string after = exercise.press(U'6');
        if (after.find(" stayed ") != std::string::npos) {
            ++stayed;
            REQUIRE(after.ends_with(" off: nearest spacing snaps it to a curve sample"));
            REQUIRE(after.starts_with("GOAL: in-between 1 stayed "));
        } else {
            REQUIRE(after != before); // it moved: its distance is said, not the why
        }
        before = after;
    }
    // Nearest spacing keeps in-between 1 on one sample for several steps of +0.05 (issue 43: four).
    REQUIRE(stayed >= 1);
}

TEST_CASE("apcs.log gets a line for a goal the student leaves and the recording keeps the student's keys as tokens "
          "after the GOAL line",
          "[lesson][replay][goal][record]")
{
    Exercise exercise("exercise-1-tension.keys");
    for (const char32_t key : {U'L', U'6'})
        exercise.press(key);
    exercise.press(U'q');
    exercise.press(U'Y');
    REQUIRE(exercise.logged == std::vector<std::string>{"goal not reached: tension +0.20, want +0.40 to +0.60"});

    Exercise reached("exercise-1-tension.keys");
    for (const char32_t key : {U'L', U'L', U'L', U'6'})
        reached.press(key);
    const std::string recorded = reached.replay->recording().text();
    CAPTURE(recorded);
    REQUIRE(recorded.starts_with("INPUT key1.dat CRC32 de215594\nINPUT key2.dat CRC32 b2c6a1da\nINPUT way1.dat CRC32 "
                                 "1db7d833\nENTER\nENTER\nTEXT 0 90 100\n"));
    REQUIRE(recorded.find("\nSTART\n") != std::string::npos);
    // Three L reach +0.45: the closing caption follows them, then the key typed after the goal.
    REQUIRE(recorded.ends_with("GOAL VALUE TENSION 0.4 0.6\nL\nL\nL\n;; " + reached.script.captions.back().text + "\n6\n"));
    // Replayed headless on fresh inputs, the recording reaches the goal again.
    const KeyScript again = [&] {
        Expected<KeyScript> script = parse_captioned_key_script(recorded, "mine.keys");
        REQUIRE(script);
        return std::move(*script);
    }();
    REQUIRE(again.goals.size() == 1);
    MemoryFiles files = example_files("exercises");
    Session session({}, files);
    ReplayDriver recheck(session, again, "mine.keys", {}, {}, ReplayAudience::headless);
    play_to_idle(recheck);
    recheck.finish();
    REQUIRE(recheck.goals());
    REQUIRE(recheck.goal_outcomes().size() == 1);
    REQUIRE(recheck.goal_outcomes()[0].verdict == GoalOutcome::Verdict::reached);
    // As the path stood when the recording ended (SPEC 3.2): the 6 typed after the goal counts.
    REQUIRE(recheck.goal_outcomes()[0].progress.value == "+0.50");
}

TEST_CASE("a goal's feedback in a few words says the quantity and what the goal wants", "[lesson][goal]")
{
    GoalProgress progress{false, "0.39", "the curve passes 0.39 from (1.50, -2.00, 2.50)", "want within 0.10", {},
                          "0.39 off"};
    CHECK(goal_feedback_briefly(progress) == "GOAL: 0.39 off, want within 0.10");
    progress.hint = "the region (points 3 to 3) cannot move span 1 to 2, nearest the goal";
    CHECK(goal_feedback_briefly(progress) == "GOAL: 0.39 off, want within 0.10");
    progress = {true, "+0.45", "tension +0.45", "want +0.40 to +0.60", {}, "tension +0.45"};
    CHECK(goal_feedback_briefly(progress) == "GOAL REACHED: tension +0.45");
}

TEST_CASE("a goal left says its verdict whole where it fits the message line, else in a few words", "[lesson][goal]")
{
    const GoalProgress tension{false, "+0.00", "tension +0.00", "want +0.40 to +0.60", {}, "tension +0.00"};
    CHECK(goal_verdict_line("skipped", tension) == "GOAL skipped: tension +0.00, want +0.40 to +0.60");
    CHECK(goal_verdict_line("not reached", tension) == "GOAL not reached: tension +0.00, want +0.40 to +0.60");
    const GoalProgress near{false, "0.39", "the curve passes 0.39 from (1.50, -2.00, 2.50)", "want within 0.10", {},
                            "0.39 off"};
    // 76 columns: fits the 79 of the message line; with "not reached", 80 do not.
    CHECK(goal_verdict_line("skipped", near) ==
          "GOAL skipped: the curve passes 0.39 from (1.50, -2.00, 2.50), want within 0.10");
    CHECK(goal_verdict_line("not reached", near) == "GOAL not reached: 0.39 off, want within 0.10");
}

TEST_CASE("the help over a paced replay keeps its title and last line: no caption or badge is laid over it",
          "[lesson][replay][goal]")
{
    // At 80x24 a caption pushed the help's title off the top and the badge covered its first key
    // line ("4, Left, 6, Right  the value one step left, righ key ENTER | caption 2 of 3").
    Exercise exercise("exercise-2-continuity.keys");
    exercise.replay->handle(KeyEvent::typed(U'?'));
    play_to_idle(*exercise.replay);
    const ProgramScreen help = exercise.replay->screen();
    REQUIRE_FALSE(help.graphics);
    CHECK(help.caption.empty());
    CHECK(help.badge.empty());
    // As the terminal lays it out (with_caption): the title on the top row, the last line last.
    const ProgramScreen shown = with_caption(help, help.caption);
    CHECK(shown.text.row_text(0).starts_with("APCS help - the keys of step 4: four-line staff"));
    CHECK(shown.text.row_text(shown.text.rows() - 1).starts_with("Any key closes this help."));
    // Closed, the task is on the caption row again and the goal on the message line.
    exercise.replay->handle(KeyEvent::typed(U'x'));
    play_to_idle(*exercise.replay);
    CHECK(exercise.replay->screen().caption ==
          "Exercise 2: a corner at the middle point: CONTINUITY from -0.60 to -0.40");
    CHECK(message_line(*exercise.replay).starts_with("GOAL: "));
}
