#pragma once

#include "apcs/input/command.h"
#include "apcs/input/key_map.h"

namespace apcs {

// The steps of thesis Ch. 4.2, one phase per prompt or screen. Headless runs name each phase as
// they print its final screen (phase_name), so the names are part of the transcript.
enum class SessionPhase {
    ask_key1,
    ask_key2,
    splitting, // writing ani1.dat … aniN.dat, a batch per Session::work()
    ask_view,
    ask_path_file,
    ask_slopes,
    choose_control,
    pick_region_first,
    pick_region_last,
    staff,
    waypoints, // the waypoint editor, opened with W at the choice of control
    ask_again,
    ask_next_path,
    ask_stop,
    ask_draw,
    animating,
    animation_done,
    overlay,
    finished,
};

const char* phase_name(SessionPhase phase);

// Whether `command`, met in `context`, is known to leave the step where it is: typing a line, a
// staff step, the region's arrow, a waypoint edit. A headless transcript prints each step's last
// screen, the one before the key that ends it: it draws a screen only before a key this does not
// vouch for. False says nothing (the command may end its step or not).
bool stays_in_phase(KeyContext context, const Command& command);

} // namespace apcs
