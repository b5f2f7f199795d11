// SPEC §3.2: PgDn K shows caption K beside the screen its keys made, which is what the handout's
// page K shows: at 80x24 every row below the badge's is the same. An exercise's too, its task's page
// with the goal's feedback and mark; past the goal the projector has skipped it where the handout's
// headless run found it not reached, and each says so in its own words.
#include "apcs/lesson/handout.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/screens/replay_caption.h"

#include "support/replay_deck.h"
#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace apcs;
namespace fs = std::filesystem;

namespace {

// The rows of a screen's text after the first (the badge's row on a terminal).
std::string below_badge_row(const std::string& text) { return text.substr(text.find('\n') + 1); }

std::vector<std::string> rows_of(const std::string& text)
{
    std::vector<std::string> rows;
    std::istringstream lines(text);
    for (std::string row; std::getline(lines, row);)
        rows.push_back(row);
    return rows;
}

// A caption row's text without the bar's padding and the "..." that ends a caption cut.
std::string uncut(std::string row)
{
    while (row.ends_with(' '))
        row.pop_back();
    if (row.ends_with("..."))
        row.resize(row.size() - 3);
    return row;
}

// The projector's row and the handout's are the same but for the verdict's words at their start:
// the rest of the handout's row (cut four columns sooner, where the caption does not fit the row)
// begins the projector's.
bool same_but_verdict(const std::string& shown, const std::string& page, const std::string& skipped,
                      const std::string& not_reached)
{
    if (!shown.starts_with(skipped) || !page.starts_with(not_reached))
        return false;
    const std::string shown_rest = uncut(shown.substr(skipped.size()));
    const std::string page_rest = uncut(page.substr(not_reached.size()));
    return shown_rest.starts_with(page_rest);
}

// The screen after PgDn skipped the goal against the handout's page of the goal not reached: every
// row the same but the message line (GOAL skipped / GOAL not reached, the same quantities, in a few
// words where the whole does not fit) and the caption row ((skipped) / (not reached)).
void require_same_but_verdicts(const std::string& shown, const std::string& page)
{
    const std::vector<std::string> shown_rows = rows_of(shown);
    const std::vector<std::string> page_rows = rows_of(page);
    REQUIRE(shown_rows.size() == page_rows.size());
    int verdict_rows = 0;
    for (std::size_t row = 0; row < shown_rows.size(); ++row) {
        if (shown_rows[row] == page_rows[row])
            continue;
        INFO("row " << row << "\nprojector: " << shown_rows[row] << "\nhandout:   " << page_rows[row]);
        const bool message = shown_rows[row].starts_with(" GOAL skipped: ") &&
                             page_rows[row].starts_with(" GOAL not reached: ");
        REQUIRE((message || same_but_verdict(shown_rows[row], page_rows[row], " (skipped) ", " (not reached) ")));
        ++verdict_rows;
    }
    REQUIRE(verdict_rows == 2);
}

// A fresh copy of the shipped exercises (their folder's files, not answers/) and the handout of
// `script` played there headless, with its exit status.
struct ExerciseHandout {
    test::TempFolder work;
    test::TempFolder handout;
    int status = 0;
    std::string err;

    explicit ExerciseHandout(const fs::path& script)
    {
        for (const auto& entry : fs::directory_iterator(test::data_folder / "exercises"))
            if (entry.is_regular_file())
                fs::copy_file(entry.path(), work / entry.path().filename().string());
        fs::remove(handout.path());
        const auto made = test::run_apcs({"--keys", script.string(), "--workdir", work.path().string(), "--handout",
                                          handout.path().string(), "--glyphs", "ascii"});
        status = made.status;
        err = made.err;
    }
};

} // namespace

TEST_CASE("each PgDn of a lesson shows at 80x24 what the handout's page for that caption shows, every row below "
          "the badge's",
          "[lesson][replay][deck][handout]")
{
    const std::string name = GENERATE(as<std::string>{}, "lesson.keys", "lesson-waypoints.keys",
                                      "lesson-continuity.keys", "lesson-bias.keys", "lesson-regions.keys",
                                      "lesson-acceleration.keys", "lesson-surface.keys");
    CAPTURE(name);
    const fs::path lessons = test::data_folder / "n-to-l";
    const test::TempFolder work;
    for (const auto& entry : fs::directory_iterator(lessons))
        fs::copy_file(entry.path(), work / entry.path().filename().string());
    const test::TempFolder handout;
    fs::remove(handout.path());
    const auto made = test::run_apcs({"--keys", (work / name).string(), "--workdir", work.path().string(), "--handout",
                                      handout.path().string(), "--glyphs", "ascii"});
    INFO(made.err);
    REQUIRE(made.status == 0);

    const KeyScript script = test::read_script(lessons / name);
    test::Deck deck(script, "n-to-l");
    std::size_t pages = 0;
    for (std::size_t caption = 0; caption < script.captions.size(); ++caption) {
        deck.press(KeyEvent::of(Key::page_down));
        const ProgramScreen shown = deck.replay->screen();
        INFO("caption " << caption + 1 << ": " << script.captions[caption].text);
        REQUIRE(shown.caption == script.captions[caption].text);
        const fs::path page = handout / (handout_file_stem(static_cast<int>(caption) + 1, script.captions.size(),
                                                           script.captions[caption].text) +
                                         ".txt");
        if (!fs::exists(page)) // an empty prompt has no page (handout.h)
            continue;
        ++pages;
        REQUIRE(below_badge_row(screen_text(with_caption(shown, shown.caption), GlyphSet::ascii)) ==
                below_badge_row(test::read_all(page)));
    }
    REQUIRE(pages + 1 >= script.captions.size());
}

TEST_CASE("each PgDn of an exercise shows at 80x24 the handout's page: the task's with the goal's feedback, the "
          "closing caption's with the verdict",
          "[lesson][replay][deck][handout]")
{
    const std::string name = GENERATE(as<std::string>{}, "exercise-1-tension.keys", "exercise-2-continuity.keys",
                                      "exercise-3-bias.keys", "exercise-4-near.keys", "exercise-5-inbetween.keys");
    CAPTURE(name);
    const fs::path exercises = test::data_folder / "exercises";
    const ExerciseHandout made(exercises / name);
    INFO(made.err);
    REQUIRE(made.status == 1); // no answer: the goal is not reached
    const fs::path& handout = made.handout.path();

    const KeyScript script = test::read_script(exercises / name);
    REQUIRE(script.goals.size() == 1);
    const std::size_t task = script.goals[0].captions_before - 1;
    test::Deck deck(script, "exercises");
    for (std::size_t caption = 0; caption < script.captions.size(); ++caption) {
        deck.press(KeyEvent::of(Key::page_down));
        const ProgramScreen shown = deck.replay->screen();
        INFO("caption " << caption + 1 << ": " << shown.caption);
        const fs::path page = handout / (handout_file_stem(static_cast<int>(caption) + 1, script.captions.size(),
                                                           script.captions[caption].text) +
                                         ".txt");
        REQUIRE(fs::exists(page));
        const std::string projected = below_badge_row(screen_text(with_caption(shown, shown.caption), GlyphSet::ascii));
        const std::string printed = below_badge_row(test::read_all(page));
        if (caption < task)
            REQUIRE(projected == printed);
        else if (caption == task) {
            REQUIRE(deck.replay->state() == ReplayState::at_goal);
            REQUIRE(printed.find(" GOAL: ") != std::string::npos);
            REQUIRE(projected == printed);
        } else {
            REQUIRE(shown.caption.starts_with(skipped_caption_prefix));
            REQUIRE(printed.find(std::string(not_reached_caption_prefix)) != std::string::npos);
            require_same_but_verdicts(projected, printed);
        }
    }
}

TEST_CASE("an answer's handout shows its goal reached: no page says 'not reached', and the task's feedback is gone "
          "once the answer's keys play",
          "[lesson][handout]")
{
    const std::string name = GENERATE(as<std::string>{}, "exercise-1-tension", "exercise-4-near",
                                      "exercise-5-inbetween");
    CAPTURE(name);
    const fs::path answer = test::data_folder / "exercises" / "answers" / (name + "-answer.keys");
    const ExerciseHandout made(answer);
    INFO(made.err);
    REQUIRE(made.status == 0);
    std::size_t pages = 0;
    for (const auto& entry : fs::directory_iterator(made.handout.path())) {
        if (entry.path().extension() != ".txt")
            continue;
        ++pages;
        const std::string page = test::read_all(entry.path());
        INFO(entry.path().filename().string() << '\n' << page);
        CHECK(page.find("not reached") == std::string::npos);
        CHECK(page.find(" GOAL: ") == std::string::npos);
        // The goal's point is marked only while its answer plays: no page shows it.
        CHECK(page.find('@') == std::string::npos);
    }
    REQUIRE(pages == test::read_script(answer).captions.size());
}

TEST_CASE("on a terminal a caption closing a goal is never said 'not reached': PgUp replays the answer",
          "[lesson][replay][deck][goal]")
{
    // The goal reached (its closing caption shown), then left and the path accepted: not reached;
    // PgUp goes back to the closing caption, its answer played again.
    const KeyScript script =
        test::read_script(test::data_folder / "exercises" / "answers" / "exercise-1-tension-answer.keys");
    test::Deck deck(script, "exercises");
    for (const KeyEvent key : {KeyEvent::of(Key::page_down), KeyEvent::of(Key::page_down), KeyEvent::typed(U'L'),
                               KeyEvent::typed(U'L'), KeyEvent::typed(U'L'), KeyEvent::typed(U'6'),
                               KeyEvent::of(Key::escape), KeyEvent::typed(U'L'), KeyEvent::of(Key::enter),
                               KeyEvent::of(Key::enter), KeyEvent::of(Key::enter), KeyEvent::of(Key::enter),
                               KeyEvent::typed(U'N')})
        deck.press(key);
    REQUIRE_FALSE(deck.replay->goal_outcomes().empty());
    REQUIRE(deck.replay->goal_outcomes()[0].verdict == GoalOutcome::Verdict::not_reached);
    deck.press(KeyEvent::of(Key::page_up));
    const ProgramScreen shown = deck.replay->screen();
    INFO(shown.caption);
    REQUIRE_FALSE(shown.caption.empty());
    REQUIRE_FALSE(shown.caption.starts_with(not_reached_caption_prefix));
}
