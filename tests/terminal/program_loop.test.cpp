// The one terminal loop (run_program_on) on a fake terminal: what it paints and when, which keys
// reach the program, resizes and Ctrl-L, the animation's ticks: the values below are worked out by
// hand from the loop's rule (paint when the screen or the terminal changed, not while keys that
// came together are still read unless 100 ms went unpainted).
#include "apcs/terminal/program_loop.h"

#include "apcs/lesson/handout.h"
#include "apcs/screens/replay_caption.h"

#include "support/fake_terminal.h"
#include "support/replay_support.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace apcs;
using test::FakeTerminal;

namespace {

// A program whose text screen says how many keys it took ("keys: 3") and, while it animates,
// which frame it shows; q ends it.
class KeyCounter final : public InteractiveProgram {
public:
    int frames_left = 0;
    int work_left = 0; // busy until it is done, a unit a work()
    int ticks = 0;
    std::vector<KeyEvent> handled;

    void handle(const KeyEvent& event) override
    {
        handled.push_back(event);
        ++m_revision;
    }
    void tick() override
    {
        ++ticks;
        if (frames_left > 0) {
            --frames_left;
            ++m_revision;
        }
    }
    bool busy() const override { return work_left > 0; }
    void work() override
    {
        --work_left;
        ++m_revision;
    }
    bool finished() const override { return !handled.empty() && handled.back() == KeyEvent::typed(U'q'); }
    bool animating() const override { return frames_left > 0; }
    int delay_ms() const override { return 50; }
    ProgramScreen screen() const override
    {
        ProgramScreen screen;
        screen.text = CellGrid(80, 24);
        screen.text.put_text(0, 0, "keys: " + std::to_string(handled.size()));
        screen.text.put_text(0, 1, "frames left: " + std::to_string(frames_left));
        screen.text.put_text(0, 3, "work left: " + std::to_string(work_left));
        return screen;
    }
    std::uint64_t screen_revision() const override { return m_revision; }

private:
    std::uint64_t m_revision = 1;
};

struct Loop {
    FakeTerminal terminal;
    TerminalPixels pixels{terminal, PixelDecision{}};
    KeyCounter program;

    ExitStatus run() { return run_program_on(program, terminal, pixels, GlyphSet::ascii); }

    // The first row of every screen painted: "keys: N".
    std::vector<std::string> painted_counts() const
    {
        std::vector<std::string> counts;
        for (const CellGrid& grid : terminal.shown)
            counts.push_back(FakeTerminal::row_of(grid, 0));
        return counts;
    }
};

} // namespace

TEST_CASE("the loop paints the first screen before it reads a key, and a key's answer before it waits again",
          "[terminal][loop]")
{
    Loop loop;
    loop.terminal.inputs = {FakeTerminal::typed(U'a')};
    REQUIRE(loop.run() == ExitStatus::stopped); // the fake's end: the loop would wait for ever
    REQUIRE(loop.painted_counts() == std::vector<std::string>{"keys: 0", "keys: 1"});
    REQUIRE(loop.terminal.shown_whole == std::vector<bool>{true, false});
    // Waits for ever for the first key, looks once more (0 ms) after it, paints, waits again.
    REQUIRE(loop.terminal.waits == std::vector<int>{-1, 0, -1});
}

TEST_CASE("keys that come together are all taken before the screen is painted once", "[terminal][loop]")
{
    Loop loop;
    loop.terminal.inputs = {FakeTerminal::typed(U'a'), FakeTerminal::typed(U'b'), FakeTerminal::typed(U'c'),
                            FakeTerminal::typed(U'd')};
    loop.run();
    REQUIRE(loop.program.handled.size() == 4);
    REQUIRE(loop.painted_counts() == std::vector<std::string>{"keys: 0", "keys: 4"});
}

TEST_CASE("a flood of keys is painted at least every tenth of a second", "[terminal][loop]")
{
    // A key every 30 ms: after the first paint (at 0 ms) the keys read at 30, 60 and 90 ms wait;
    // the 4th, at 120 ms, is 100 ms or more after it, and so on; the 10th and last is painted once
    // the look for more finds none.
    Loop loop;
    for (int key = 0; key < 10; ++key)
        loop.terminal.inputs.push_back(FakeTerminal::typed(U'a'));
    loop.terminal.per_read = std::chrono::milliseconds(30);
    loop.run();
    REQUIRE(loop.painted_counts() == std::vector<std::string>{"keys: 0", "keys: 4", "keys: 8", "keys: 10"});
}

TEST_CASE("a program that ends ends the loop with success, its last key's screen left unpainted", "[terminal][loop]")
{
    Loop loop;
    loop.terminal.inputs = {FakeTerminal::typed(U'a'), FakeTerminal::typed(U'q'), FakeTerminal::typed(U'b')};
    REQUIRE(loop.run() == ExitStatus::success);
    REQUIRE(loop.program.handled.size() == 2); // b is never read
    REQUIRE(loop.painted_counts() == std::vector<std::string>{"keys: 0"});
}

TEST_CASE("below 80x23 the screen says how large it must be and keys wait, back at 80x24 every cell is painted",
          "[terminal][loop]")
{
    Loop loop;
    loop.terminal.inputs = {FakeTerminal::resize({60, 20}), FakeTerminal::typed(U'a'), FakeTerminal::resize({80, 23}),
                            FakeTerminal::typed(U'b')};
    loop.run();
    REQUIRE(loop.program.handled == std::vector<KeyEvent>{KeyEvent::typed(U'b')});
    const std::vector<CellGrid>& shown = loop.terminal.shown;
    // 80x24, 60x20 (a is not the program's), 80x23, and b's answer.
    REQUIRE(shown.size() == 4);
    CHECK(shown[1].columns() == 60);
    CHECK(FakeTerminal::row_of(shown[1], 10).find("The terminal must be at least 80x23 (it is 60x20)") !=
          std::string::npos);
    CHECK(FakeTerminal::row_of(shown[1], 11).find("Keys are ignored until it is larger") != std::string::npos);
    // The short screen: 80x23, the text screen's first blank row left out.
    CHECK(shown[2].rows() == 23);
    CHECK(FakeTerminal::row_of(shown[2], 0) == "keys: 0");
    CHECK(FakeTerminal::row_of(shown[3], 0) == "keys: 1");
    REQUIRE(loop.terminal.shown_whole == std::vector<bool>{true, true, true, false});
}

TEST_CASE("Ctrl-L clears the terminal and paints every cell again, and the program sees the key too",
          "[terminal][loop]")
{
    Loop loop;
    loop.terminal.inputs = {FakeTerminal::key(KeyEvent::of(Key::redraw))};
    loop.run();
    REQUIRE(loop.terminal.redraws == 1);
    REQUIRE(loop.program.handled == std::vector<KeyEvent>{KeyEvent::of(Key::redraw)});
    REQUIRE(loop.terminal.shown_whole == std::vector<bool>{true, true});
}

TEST_CASE("an animation is ticked every delay_ms and painted each frame, a screen that did not change is not "
          "painted again",
          "[terminal][loop]")
{
    Loop loop;
    loop.program.frames_left = 3;
    loop.run();
    REQUIRE(loop.program.ticks == 3);
    // The first screen and each of the three frames; then the loop waits for a key.
    REQUIRE(loop.terminal.shown.size() == 4);
    REQUIRE(FakeTerminal::row_of(loop.terminal.shown.back(), 1) == "frames left: 0");
    REQUIRE(loop.terminal.waits == std::vector<int>{50, 50, 50, -1});
}

TEST_CASE("a lesson's PgDn through the loop paints at 80x24 the handout's page of its caption below the badge's row",
          "[terminal][loop][deck]")
{
    const KeyScript script = test::read_script(test::data_folder / "n-to-l" / "lesson.keys");
    REQUIRE(script.captions.size() >= 2);
    // The handout's pages, headless (as --handout writes them).
    std::vector<std::string> pages;
    {
        MemoryFiles files = test::example_files("n-to-l");
        Session session({}, files);
        ReplayHooks hooks;
        hooks.caption_ended = [&](std::size_t, const std::string& caption, const ProgramScreen& screen,
                                  const std::vector<std::string>&) {
            pages.push_back(screen_text(with_caption(screen, caption), GlyphSet::ascii));
        };
        ReplayDriver replay(session, script, "lesson.keys", ReplayPace{}, hooks, ReplayAudience::headless);
        play_to_idle(replay);
        replay.finish();
    }
    REQUIRE(pages.size() == script.captions.size());

    MemoryFiles files = test::example_files("n-to-l");
    Session session({}, files);
    ReplayDriver replay(session, script, "lesson.keys", ReplayPace{ReplayPace::Kind::on_space, 0}, {},
                        ReplayAudience::terminal);
    FakeTerminal terminal;
    TerminalPixels pixels(terminal, PixelDecision{});
    terminal.inputs = {FakeTerminal::key(KeyEvent::of(Key::page_down)), FakeTerminal::key(KeyEvent::of(Key::page_down))};
    run_program_on(replay, terminal, pixels, GlyphSet::ascii);
    const CellGrid& painted = terminal.shown.back();
    std::string below_badge;
    for (int row = 1; row < painted.rows(); ++row)
        below_badge += FakeTerminal::row_of(painted, row) + '\n';
    REQUIRE(below_badge == pages[1].substr(pages[1].find('\n') + 1));
    REQUIRE(FakeTerminal::row_of(painted, 0).find("caption 2 of") != std::string::npos);
}

TEST_CASE("a busy program works in slices of 30 ms of the terminal's clock, painted between them", "[terminal][loop]")
{
    // Each look at the clock takes 1 ms: a slice starts at a look, and each unit of work follows a
    // look 1, 2, ... 29 ms after it; the 30th look ends the slice. 100 units: 29, 29, 29 and 13.
    Loop loop;
    loop.program.work_left = 100;
    loop.terminal.per_look = std::chrono::milliseconds(1);
    loop.run();
    std::vector<std::string> painted;
    for (const CellGrid& grid : loop.terminal.shown)
        painted.push_back(FakeTerminal::row_of(grid, 3));
    REQUIRE(painted ==
            std::vector<std::string>{"work left: 100", "work left: 71", "work left: 42", "work left: 13", "work left: 0"});
}
