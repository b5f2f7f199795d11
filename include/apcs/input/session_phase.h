#pragma once

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

} // namespace apcs
