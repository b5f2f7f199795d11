#pragma once

#include "apcs/session/session.h"
#include "apcs/base/step_log.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace apcs::test {

// Types an answer at a text prompt and presses Enter.
inline void type(Session& session, const std::string& line)
{
    for (const char c : line)
        session.handle(c == ' ' ? KeyEvent::of(Key::space) : KeyEvent::typed(static_cast<char32_t>(c)));
    session.handle(KeyEvent::of(Key::enter));
}

// What a step logs, kept for the test to read.
struct LogLines final : StepLog {
    std::vector<std::string> lines;
    void log(const std::string& line) override { lines.push_back(line); }
};

// The message line of a graphics screen (text row 18).
inline std::string message_of(const GraphicsScreen& screen)
{
    for (const TextLine& line : screen.text)
        if (line.row == 18)
            return line.text;
    return {};
}

// Three frames of a stick moving up (KEY1 k1.dat, one in-between, KEY2 k2.dat), 50 ms each.
inline AnimationPlayer stick_player(StepLog& log)
{
    FrameSequence frames(3, 2);
    for (std::size_t k = 0; k < 3; ++k) {
        frames.frame(k)[0] = {0, static_cast<double>(k), 0};
        frames.frame(k)[1] = {0, static_cast<double>(k), 1};
    }
    Graphic structure;
    structure.parts.push_back({"stick", Closure::open, {{0, 0, 0}, {0, 0, 1}}});
    return AnimationPlayer(frames, structure, {"k1.dat", "k2.dat"}, {0, 90}, 50, log);
}

// A path editor's setup for path file way1.dat with control points at `positions` (staff values 0).
inline PathEditor::Setup path_setup(std::initializer_list<Vec3> positions, const PathSettings& settings)
{
    PathEditor::Setup setup;
    setup.path_name = "way1.dat";
    for (const Vec3& position : positions)
        setup.points.push_back({position, {}});
    setup.settings = settings;
    return setup;
}

// Commands for a path editor that each leave it editing.
inline void apply(PathEditor& editor, std::initializer_list<Command> commands)
{
    for (const Command& command : commands)
        REQUIRE(editor.update(command) == PathEditor::Outcome::editing);
}

} // namespace apcs::test
