#include "apcs/input/play_to_idle.h"

namespace apcs {

void play_to_idle(InteractiveProgram& program, const IdleDrive& drive)
{
    while (!program.finished()) {
        if (drive.go_on && !drive.go_on())
            return;
        if (program.busy())
            program.work();
        else if (drive.animations == Animations::play_through && program.animating())
            program.tick();
        else
            return;
        if (drive.after_step)
            drive.after_step();
    }
}

} // namespace apcs
