// The terminal paints when the screen's revision has advanced (program_loop.cpp): the replay's
// part of it is the words it lays over the session's screen (the caption, the badge, the place).
#include "apcs/input/play_to_idle.h"
#include "apcs/lesson/replay_driver.h"

#include "support/replay_deck.h"
#include "support/replay_support.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

using namespace apcs;

namespace {

// The deck's keys and a few of the session's, the step and the path screen's among them.
const std::array<KeyEvent, 16> keys_tried = {
    KeyEvent::of(Key::space),     KeyEvent::of(Key::space),   KeyEvent::of(Key::page_down),
    KeyEvent::of(Key::page_up),   KeyEvent::of(Key::home),    KeyEvent::of(Key::escape),
    KeyEvent::of(Key::enter),     KeyEvent::typed(U'6'),      KeyEvent::typed(U'4'),
    KeyEvent::typed(U'8'),        KeyEvent::typed(U'2'),      KeyEvent::typed(U'q'),
    KeyEvent::typed(U'y'),        KeyEvent::typed(U'n'),      KeyEvent::typed(U'?'),
    KeyEvent::typed(U'L'),
};

// Each step of the replay judged alone: the screen and the revision before it, then after.
struct Watch {
    ReplayDriver& replay;
    ProgramScreen shown;
    std::uint64_t revision = 0;
    std::size_t changed = 0;
    std::size_t missed = 0;

    void before()
    {
        shown = replay.screen();
        revision = replay.screen_revision();
    }
    void after(const std::string& where)
    {
        const bool screen_changed = !(replay.screen() == shown);
        const bool revision_advanced = replay.screen_revision() != revision;
        changed += screen_changed ? 1 : 0;
        if (screen_changed != revision_advanced && ++missed <= 20)
            UNSCOPED_INFO(where << ": the screen " << (screen_changed ? "changed" : "stayed") << ", the revision "
                                << (revision_advanced ? "advanced" : "stayed"));
    }
};

} // namespace

TEST_CASE("over every lesson and exercise, paced, a deck key or a step of the replay changes the screen if and only "
          "if it advances the revision",
          "[lesson][replay][fuzz]")
{
    std::size_t scripts = 0;
    std::size_t changed = 0;
    std::size_t missed = 0;
    for (const std::string example : {"n-to-l", "exercises"})
        for (const auto& entry : std::filesystem::directory_iterator(test::data_folder / example)) {
            if (entry.path().extension() != ".keys" || entry.path().filename() == "session.keys")
                continue;
            ++scripts;
            const std::string name = entry.path().filename().string();
            Expected<KeyScript> script = parse_captioned_key_script(test::read_all(entry.path()), name);
            REQUIRE(script);
            test::Deck deck(*script, example);
            Watch watch{*deck.replay, {}};
            std::uint32_t draw = 12345;
            for (int press = 0; press < 60 && !deck.replay->finished(); ++press) {
                draw = draw * 1103515245u + 12345u; // the same keys every run
                const KeyEvent key = keys_tried[(draw >> 16) % keys_tried.size()];
                const std::string where = name + " key " + std::to_string(press);
                watch.before();
                deck.replay->handle(key);
                watch.after(where);
                IdleDrive drive;
                drive.before_step = [&] { watch.before(); };
                drive.after_step = [&] { watch.after(where + ", a step after it"); };
                play_to_idle(*deck.replay, drive);
            }
            changed += watch.changed;
            missed += watch.missed;
        }
    // 547 changes over the 12 scripts when written.
    REQUIRE(scripts >= 10);
    CHECK(missed == 0);
    REQUIRE(changed > 300);
}
