#pragma once

#include <cstdint>

#include "apcs/formats/key_event.h"
#include "apcs/screens/program_screen.h"

namespace apcs {

// What the one terminal loop (program_loop.h) drives: the session (apcs) and a scene's player
// (apcs play). Keys in, screens out; no terminal and no clock: the loop calls tick() every
// delay_ms() while animating(), and work() until busy() is false, reading keys in between.
class InteractiveProgram {
public:
    virtual ~InteractiveProgram() = default;

    virtual void handle(const KeyEvent& event) = 0;
    virtual void tick() = 0;
    virtual void work() {}
    virtual bool finished() const = 0;
    virtual bool animating() const = 0;
    virtual bool busy() const { return false; }
    virtual int delay_ms() const = 0;
    virtual ProgramScreen screen() const = 0;
    // Advanced whenever screen() would show something else: the terminal composes and paints a
    // screen only when it changed (or the terminal did).
    virtual std::uint64_t screen_revision() const = 0;
};

} // namespace apcs
