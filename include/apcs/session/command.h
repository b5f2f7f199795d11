#pragma once

#include <variant>

// What a key means to the session, once the key map (key_map.h) has read it in the context of the
// step on the screen. The steps act on commands, never on keys, so a binding is one row of the key
// map.
namespace apcs::command {

// Text prompts (thesis figs. 4.2.1–4.2.3).
struct TypeCharacter {
    char32_t character = 0;
    friend bool operator==(const TypeCharacter&, const TypeCharacter&) = default;
};
struct EraseCharacter {
    friend bool operator==(const EraseCharacter&, const EraseCharacter&) = default;
};
struct ClearLine {
    friend bool operator==(const ClearLine&, const ClearLine&) = default;
};
struct SubmitLine {
    friend bool operator==(const SubmitLine&, const SubmitLine&) = default;
};

// Check_GorL_Control: 8 Global, 2 Local.
struct ChooseGlobal {
    friend bool operator==(const ChooseGlobal&, const ChooseGlobal&) = default;
};
struct ChooseLocal {
    friend bool operator==(const ChooseLocal&, const ChooseLocal&) = default;
};
// Scan_Control_Point: the arrow moves by `points` control points.
struct ArrowMove {
    int points = 0;
    friend bool operator==(const ArrowMove&, const ArrowMove&) = default;
};
// tnextpixel: the active staff value moves by `steps` steps (4/6: one, J/L: three).
struct StaffStep {
    int steps = 0;
    friend bool operator==(const StaffStep&, const StaffStep&) = default;
};
// Enter: take what is shown (the arrow's point, the staff line's value).
struct Accept {
    friend bool operator==(const Accept&, const Accept&) = default;
};
// Esc on a staff line: leave the value as it was and go on.
struct Keep {
    friend bool operator==(const Keep&, const Keep&) = default;
};
// Esc while picking: one step back.
struct Back {
    friend bool operator==(const Back&, const Back&) = default;
};
struct ToggleKeyFrames {
    friend bool operator==(const ToggleKeyFrames&, const ToggleKeyFrames&) = default;
};

// Questions: Y/N, Enter, any key.
struct Yes {
    friend bool operator==(const Yes&, const Yes&) = default;
};
struct No {
    friend bool operator==(const No&, const No&) = default;
};
struct Continue {
    friend bool operator==(const Continue&, const Continue&) = default;
};

// Showing_Animation.
struct StopAnimation {
    friend bool operator==(const StopAnimation&, const StopAnimation&) = default;
};
struct Pause {
    friend bool operator==(const Pause&, const Pause&) = default;
};
struct Replay {
    friend bool operator==(const Replay&, const Replay&) = default;
};

} // namespace apcs::command

namespace apcs {

using Command = std::variant<command::TypeCharacter, command::EraseCharacter, command::ClearLine, command::SubmitLine,
                             command::ChooseGlobal, command::ChooseLocal, command::ArrowMove, command::StaffStep,
                             command::Accept, command::Keep, command::Back, command::ToggleKeyFrames, command::Yes,
                             command::No, command::Continue, command::StopAnimation, command::Pause, command::Replay>;

} // namespace apcs
