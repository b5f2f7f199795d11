#include "apcs/input/chart.h"

#include <array>

namespace apcs {

namespace {

// In Command's order (command.h).
constexpr std::array<std::string_view, 34> names = {
    "TypeCharacter", "EraseCharacter", "ClearLine",      "SubmitLine",   "ChooseGlobal", "ChooseLocal",
    "ArrowMove",     "StaffStep",      "Accept",         "Keep",         "Back",         "ToggleKeyFrames",
    "Zoom",          "ToggleGhost",    "ToggleTangents", "ToggleLawGraph", "PinReference", "ChoosePoint",
    "OpenValueField", "OpenWaypoints", "InsertPoint",    "DeletePoint",  "MovePoint",    "Undo",
    "Yes",           "No",             "Continue",       "ShowHelp",     "SavePicture",  "Quit",
    "StopAnimation", "Pause",          "Replay",         "StepFrame",
};
static_assert(names.size() == std::variant_size_v<Command>, "a name for every command");
static_assert(on<command::StepFrame> == 33 && on<command::Undo> == 23 && on<command::OpenValueField> == 18,
              "names in Command's order");

} // namespace

std::string_view command_name(std::size_t index) { return index < names.size() ? names[index] : "?"; }

} // namespace apcs
