#pragma once

// A paced replay on an example's files in memory, able to go back as the program's is (through
// RewindableFiles), driven as a terminal would drive it, without a terminal or a clock.
#include "apcs/input/play_to_idle.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/session/rewindable_files.h"

#include "support/replay_support.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace apcs::test {

// A script given as text, named deck.keys in its messages.
inline KeyScript parsed_deck(const std::string& text)
{
    Expected<KeyScript> script = parse_captioned_key_script(text, "deck.keys");
    REQUIRE(script);
    return std::move(*script);
}

struct Deck {
    MemoryFiles folder;
    RewindableFiles files{folder};
    SessionSettings settings;
    Session session{settings, files};
    std::vector<std::size_t> told;
    std::unique_ptr<ReplayDriver> replay;

    // `animations` says what the drive after each key does with an animation: play it through, or
    // stop at it as the terminal does until its clock ticks.
    Deck(const KeyScript& script, const std::string& example,
         ReplayPace pace = ReplayPace{ReplayPace::Kind::on_space, 0}, Animations animations = Animations::play_through,
         SessionSettings session_settings = {})
        : Deck(script, example_files(example), pace, animations, std::move(session_settings))
    {
    }

    Deck(const KeyScript& script, MemoryFiles inputs, ReplayPace pace, Animations animations,
         SessionSettings session_settings)
        : folder(std::move(inputs))
        , settings(std::move(session_settings))
        , m_drive{animations, {}, {}, {}}
    {
        ReplayHooks hooks;
        hooks.caption_reached = [this](std::size_t index, const ProgramScreen&) { told.push_back(index); };
        hooks.log = [this](const std::string& line) { files.log(line); };
        hooks.session_as_started = [this] {
            files.rewind();
            return std::make_unique<Session>(settings, files);
        };
        hooks.caught_up = [this] { files.caught_up(); };
        replay = std::make_unique<ReplayDriver>(session, script, "deck.keys", pace, hooks, ReplayAudience::terminal);
        play_to_idle(*replay, m_drive);
    }

    // A key, then the replay driven until it waits for the next.
    void press(const KeyEvent& key)
    {
        replay->handle(key);
        play_to_idle(*replay, m_drive);
    }

private:
    IdleDrive m_drive;
};

} // namespace apcs::test
