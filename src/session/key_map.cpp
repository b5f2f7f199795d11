#include "apcs/session/key_map.h"

#include <algorithm>
#include <array>
#include <vector>

namespace apcs {

namespace {

using Pattern = KeyPattern;
using Context = KeyContext;
namespace cmd = command;

constexpr std::string_view key_frames_on_off = "K key frames on/off";

constexpr std::array bindings{
    // Text prompts: every printable key is typed; Esc clears the line (SPEC §7.3).
    KeyBinding{Context::text_line, Pattern::of(Key::enter), cmd::SubmitLine{}, ""},
    KeyBinding{Context::text_line, Pattern::of(Key::backspace), cmd::EraseCharacter{}, ""},
    KeyBinding{Context::text_line, Pattern::of(Key::escape), cmd::ClearLine{}, ""},
    KeyBinding{Context::text_line, Pattern::of(Key::space), cmd::TypeCharacter{U' '}, ""},
    KeyBinding{Context::text_line, Pattern::printable(), cmd::TypeCharacter{}, ""},

    KeyBinding{Context::yes_to_go_on, Pattern::letter(U'Y'), cmd::Yes{}, ""},
    KeyBinding{Context::enter_to_go_on, Pattern::of(Key::enter), cmd::Continue{}, ""},
    KeyBinding{Context::any_key, Pattern::any_key(), cmd::Continue{}, ""},

    // Check_GorL_Control: the keypad's 8 and 2, or the arrows on them.
    KeyBinding{Context::control_choice, Pattern::exactly(U'8'), cmd::ChooseGlobal{}, ""},
    KeyBinding{Context::control_choice, Pattern::of(Key::up), cmd::ChooseGlobal{}, ""},
    KeyBinding{Context::control_choice, Pattern::exactly(U'2'), cmd::ChooseLocal{}, ""},
    KeyBinding{Context::control_choice, Pattern::of(Key::down), cmd::ChooseLocal{}, ""},
    KeyBinding{Context::control_choice, Pattern::letter(U'K'), cmd::ToggleKeyFrames{}, key_frames_on_off},

    // Scan_Control_Point: the message line says what 4/6 and Enter do.
    KeyBinding{Context::region_pick, Pattern::exactly(U'4'), cmd::ArrowMove{-1}, ""},
    KeyBinding{Context::region_pick, Pattern::of(Key::left), cmd::ArrowMove{-1}, ""},
    KeyBinding{Context::region_pick, Pattern::exactly(U'6'), cmd::ArrowMove{+1}, ""},
    KeyBinding{Context::region_pick, Pattern::of(Key::right), cmd::ArrowMove{+1}, ""},
    KeyBinding{Context::region_pick, Pattern::of(Key::enter), cmd::Accept{}, ""},
    KeyBinding{Context::region_pick, Pattern::of(Key::escape), cmd::Back{}, ""},
    KeyBinding{Context::region_pick, Pattern::letter(U'K'), cmd::ToggleKeyFrames{}, key_frames_on_off},

    // Scan_Parameters / tnextpixel (thesis fig. 3.1.5).
    KeyBinding{Context::staff, Pattern::exactly(U'4'), cmd::StaffStep{-1}, "4/6 step"},
    KeyBinding{Context::staff, Pattern::of(Key::left), cmd::StaffStep{-1}, ""},
    KeyBinding{Context::staff, Pattern::exactly(U'6'), cmd::StaffStep{+1}, "4/6 step"},
    KeyBinding{Context::staff, Pattern::of(Key::right), cmd::StaffStep{+1}, ""},
    KeyBinding{Context::staff, Pattern::letter(U'J'), cmd::StaffStep{-3}, "J/L 3 steps"},
    KeyBinding{Context::staff, Pattern::letter(U'L'), cmd::StaffStep{+3}, "J/L 3 steps"},
    KeyBinding{Context::staff, Pattern::of(Key::enter), cmd::Accept{}, "Enter accept"},
    KeyBinding{Context::staff, Pattern::of(Key::escape), cmd::Keep{}, "Esc keep"},
    KeyBinding{Context::staff, Pattern::letter(U'K'), cmd::ToggleKeyFrames{}, "K key frames"},

    // Ask_Adjusting: Y adjusts again, anything else accepts the path.
    KeyBinding{Context::adjust_again, Pattern::letter(U'K'), cmd::ToggleKeyFrames{}, key_frames_on_off},
    KeyBinding{Context::adjust_again, Pattern::letter(U'Y'), cmd::Yes{}, ""},
    KeyBinding{Context::adjust_again, Pattern::any_key(), cmd::No{}, ""},

    // Showing_Animation.
    KeyBinding{Context::animation, Pattern::of(Key::escape), cmd::StopAnimation{}, "Esc stop"},
    KeyBinding{Context::animation, Pattern::of(Key::space), cmd::Pause{}, "Space pause"},
    KeyBinding{Context::animation, Pattern::letter(U'R'), cmd::Replay{}, "R replay"},
};

char32_t upper_case(char32_t character) { return character >= U'a' && character <= U'z' ? character - 32 : character; }

} // namespace

bool KeyPattern::matches(const KeyEvent& event) const
{
    switch (kind) {
    case Kind::key: return event.key == key;
    case Kind::character: return event.key == Key::character && event.character == character;
    case Kind::letter: return event.key == Key::character && upper_case(event.character) == character;
    case Kind::printable: return event.key == Key::character && event.character >= 0x20;
    case Kind::any: return true;
    }
    return false;
}

std::span<const KeyBinding> key_bindings() { return bindings; }

std::optional<Command> command_for(KeyContext context, const KeyEvent& event)
{
    for (const KeyBinding& binding : bindings) {
        if (binding.context != context || !binding.pattern.matches(event))
            continue;
        Command command = binding.command;
        if (auto* typed = std::get_if<cmd::TypeCharacter>(&command); typed != nullptr && typed->character == 0)
            typed->character = event.character;
        return command;
    }
    return std::nullopt;
}

std::string key_help(KeyContext context)
{
    std::vector<std::string_view> shown;
    for (const KeyBinding& binding : bindings)
        if (binding.context == context && !binding.help.empty() &&
            std::find(shown.begin(), shown.end(), binding.help) == shown.end())
            shown.push_back(binding.help);
    std::string help;
    for (const std::string_view words : shown)
        help += (help.empty() ? "" : "  ") + std::string(words);
    return help;
}

} // namespace apcs
