#pragma once

#include "apcs/input/interactive_program.h"

#include <functional>

namespace apcs {

// What play_to_idle does with an animation: plays it to its end, nobody waiting for the clock (a
// replay headless, apcs grade, a test), or stops at it (the terminal: the clock is its loop's).
enum class Animations { play_through, stop_at };

struct IdleDrive {
    Animations animations = Animations::play_through;
    // Asked before each step: false ends the drive there (the terminal's slice of time is up).
    std::function<bool()> go_on;
    // Called after each step the program took (the headless transcript looks at the screen).
    std::function<void()> after_step;
    // Called before each step, once go_on has let it be taken.
    std::function<void()> before_step;
};

// The one loop that drives a program until it has nothing to do without a key: work() while it
// is busy and, as `drive` says, tick() while it animates. The terminal, the headless replay, apcs
// grade, a replay going back to a caption and the tests all drive a program through it.
void play_to_idle(InteractiveProgram& program, const IdleDrive& drive = {});

} // namespace apcs
