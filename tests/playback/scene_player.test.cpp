#include "apcs/playback/scene_player.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace apcs;
using apcs::test::message_of;

namespace {

// The stick's three frames as a scene's player shows them.
AnimationPlayer scene_stick_player(StepLog& log)
{
    AnimationPlayer player = test::stick_player(log);
    player.name_frames_by_scene("stick.scn");
    return player;
}

std::string message_of(const ScenePlayer& program)
{
    const ProgramScreen screen = program.screen();
    REQUIRE(screen.graphics);
    return test::message_of(screen.picture);
}

} // namespace

TEST_CASE("apcs play's q ends the player at once, without the session's quit question", "[session][play]")
{
    test::LogLines log;
    AnimationPlayer player = scene_stick_player(log);
    ScenePlayer program(player, 50, [](const GraphicsScreen&) { return std::string(); });
    REQUIRE(program.animating());
    program.handle(KeyEvent::typed('q'));
    REQUIRE(program.finished());
}

TEST_CASE("apcs play's help screen lists the player's keys and holds the frames until a key closes it",
          "[session][play]")
{
    test::LogLines log;
    AnimationPlayer player = scene_stick_player(log);
    ScenePlayer program(player, 50, [](const GraphicsScreen&) { return std::string(); });
    program.handle(KeyEvent::typed('?'));
    const ProgramScreen help = program.screen();
    REQUIRE_FALSE(help.graphics);
    REQUIRE(help.text.row_text(0).find("playing a scene") != std::string::npos);
    // The loop ticks only while the program animates: the frames wait under the help.
    REQUIRE_FALSE(program.animating());
    program.handle(KeyEvent::typed('x'));
    REQUIRE(program.animating());
    REQUIRE_FALSE(program.finished());
    REQUIRE(message_of(program) == "Frame 0 of 2: stick.scn");
}

TEST_CASE("apcs play's P hands the screen shown to the picture saver and says what it answered", "[session][play]")
{
    test::LogLines log;
    AnimationPlayer player = scene_stick_player(log);
    int pictures = 0;
    ScenePlayer program(player, 50, [&pictures](const GraphicsScreen& screen) {
        ++pictures;
        return "wrote apcs001.png (" + test::message_of(screen) + ")";
    });
    program.tick();
    program.handle(KeyEvent::typed('P'));
    REQUIRE(pictures == 1);
    REQUIRE(message_of(program) == "wrote apcs001.png (Frame 1 of 2: stick.scn)");
}

TEST_CASE("apcs play ends after the frames overlaid, as the session's animation does", "[session][play]")
{
    test::LogLines log;
    AnimationPlayer player = scene_stick_player(log);
    ScenePlayer program(player, 50, [](const GraphicsScreen&) { return std::string(); });
    program.handle(KeyEvent::of(Key::escape));
    REQUIRE_FALSE(program.animating());
    program.handle(KeyEvent::typed('x'));
    REQUIRE(player.leaf() == AnimationPlayer::State::overlaid);
    REQUIRE_FALSE(program.finished());
    program.handle(KeyEvent::typed('x'));
    REQUIRE(program.finished());
}

TEST_CASE("Ctrl-L repaints apcs play's screen and neither closes its help nor ends it", "[session][play]")
{
    test::LogLines log;
    AnimationPlayer player = scene_stick_player(log);
    ScenePlayer program(player, 50, [](const GraphicsScreen&) { return std::string(); });
    program.handle(KeyEvent::typed('?'));
    program.handle(KeyEvent::of(Key::redraw));
    REQUIRE_FALSE(program.screen().graphics);
    program.handle(KeyEvent::typed('x'));
    program.handle(KeyEvent::of(Key::escape));
    program.handle(KeyEvent::typed('x'));
    REQUIRE(player.leaf() == AnimationPlayer::State::overlaid);
    program.handle(KeyEvent::of(Key::redraw));
    REQUIRE_FALSE(program.finished());
}
