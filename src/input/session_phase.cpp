#include "apcs/input/session_phase.h"

#include <variant>

namespace apcs {

const char* phase_name(SessionPhase phase)
{
    switch (phase) {
    case SessionPhase::ask_key1: return "step 1: KEY1 file";
    case SessionPhase::ask_key2: return "step 1: KEY2 file";
    case SessionPhase::splitting: return "step 1: splitting into path files";
    case SessionPhase::ask_view: return "step 2: view and delay";
    case SessionPhase::ask_path_file: return "step 3: path file";
    case SessionPhase::ask_slopes: return "step 3: end slopes";
    case SessionPhase::choose_control: return "step 3: global or local control";
    case SessionPhase::pick_region_first: return "step 3: first control point of the region";
    case SessionPhase::pick_region_last: return "step 3: last control point of the region";
    case SessionPhase::staff: return "step 4: four-line staff";
    case SessionPhase::waypoints: return "step 3: waypoint editor";
    case SessionPhase::ask_again: return "step 5: adjust again";
    case SessionPhase::ask_next_path: return "step 5: next path";
    case SessionPhase::ask_stop: return "step 6: stop the work";
    case SessionPhase::ask_draw: return "step 6: surface fitting done";
    case SessionPhase::animating: return "step 6: animation";
    case SessionPhase::animation_done: return "step 6: animation done";
    case SessionPhase::overlay: return "step 6: all frames";
    case SessionPhase::finished: return "end";
    }
    return "";
}

bool stays_in_phase(KeyContext context, const Command& command)
{
    const auto is = [&command]<typename... Kinds>(Kinds...) { return (std::holds_alternative<Kinds>(command) || ...); };
    using namespace command;
    switch (context) {
    case KeyContext::text_line:
    case KeyContext::value_field: return is(TypeCharacter{}, EraseCharacter{});
    case KeyContext::staff: return is(StaffStep{});
    case KeyContext::region_pick: return is(ArrowMove{});
    case KeyContext::waypoints: return is(ChoosePoint{}, MovePoint{}, InsertPoint{}, DeletePoint{}, Undo{}, Zoom{});
    default: return false;
    }
}

} // namespace apcs
