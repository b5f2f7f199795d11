#include "apcs/input/play_to_idle.h"

namespace apcs {

void play_to_idle(InteractiveProgram& program, const IdleDrive& drive)
{
    while (!program.finished()) {
        if (drive.go_on && !drive.go_on())
            return;
        const bool busy = program.busy();
        if (!busy && !(drive.animations == Animations::play_through && program.animating()))
            return;
        if (drive.before_step)
            drive.before_step();
        if (busy)
            program.work();
        else
            program.tick();
        if (drive.after_step)
            drive.after_step();
    }
}

} // namespace apcs
