#pragma once

#include <variant>

// What a key means to the session, once the key map (key_map.h) has read it in the context of the
// step on the screen. The steps act on commands, never on keys, so a binding is one row of the key
// map.
namespace apcs::command {

// A command that carries nothing but itself: any two are equal.
template <typename Self>
struct Signal {
    friend constexpr bool operator==(const Self&, const Self&) { return true; }
};

// Text prompts (thesis figs. 4.2.1–4.2.3).
struct TypeCharacter {
    char32_t character = 0;
    friend bool operator==(const TypeCharacter&, const TypeCharacter&) = default;
};
struct EraseCharacter : Signal<EraseCharacter> {};
struct ClearLine : Signal<ClearLine> {};
struct SubmitLine : Signal<SubmitLine> {};

// Check_GorL_Control: 8 Global, 2 Local.
struct ChooseGlobal : Signal<ChooseGlobal> {};
struct ChooseLocal : Signal<ChooseLocal> {};
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
struct Accept : Signal<Accept> {};
// Esc on a staff line: leave the value as it was and go on.
struct Keep : Signal<Keep> {};
// Esc while picking: one step back.
struct Back : Signal<Back> {};
struct ToggleKeyFrames : Signal<ToggleKeyFrames> {};
// Z: the path screen's view magnified ×2, ×4, ×8 and back to fitted; O: the ghost of the curve as
// it was before the last change shown or hidden (SPEC §7.2.1).
struct Zoom : Signal<Zoom> {};
struct ToggleGhost : Signal<ToggleGhost> {};

// Teaching and editing on the path screen (thesis Ch. 6's future work).
// T: the tangents DS and DD drawn at every control point; G: the inset graph of the span's law.
struct ToggleTangents : Signal<ToggleTangents> {};
struct ToggleLawGraph : Signal<ToggleLawGraph> {};
// C: the curve as it is pinned as reference A beside the live one, or unpinned (SPEC §3.1).
struct PinReference : Signal<PinReference> {};
// Tab, Shift-Tab, ] and [: another control point chosen, `by` points on.
struct ChoosePoint {
    int by = 0;
    friend bool operator==(const ChoosePoint&, const ChoosePoint&) = default;
};
// =: a field on the message line for typing the staff line's value.
struct OpenValueField : Signal<OpenValueField> {};
// W: the waypoint editor. I inserts a control point after the chosen one, D deletes it, the moves
// shift it by steps: right and up on the screen, toward the viewer.
struct OpenWaypoints : Signal<OpenWaypoints> {};
struct InsertPoint : Signal<InsertPoint> {};
struct DeletePoint : Signal<DeletePoint> {};
struct MovePoint {
    int right = 0;
    int up = 0;
    int toward = 0;
    friend bool operator==(const MovePoint&, const MovePoint&) = default;
};
// U: the last change of the path taken back.
struct Undo : Signal<Undo> {};

// Questions: Y/N, Enter, any key.
struct Yes : Signal<Yes> {};
struct No : Signal<No> {};
struct Continue : Signal<Continue> {};

// Everywhere a key may mean them (SPEC §3, §7.3): the help screen of the step, a picture of the
// screen (apcsNNN.png), ending the session, and closing the help screen.
struct ShowHelp : Signal<ShowHelp> {};
struct SavePicture : Signal<SavePicture> {};
struct Quit : Signal<Quit> {};

// Showing_Animation.
struct StopAnimation : Signal<StopAnimation> {};
struct Pause : Signal<Pause> {};
struct Replay : Signal<Replay> {};
// , and .: the frame before or after, the animation paused (SPEC §3.1: a class follows it frame by frame).
struct StepFrame {
    int by = 0;
    friend bool operator==(const StepFrame&, const StepFrame&) = default;
};

} // namespace apcs::command

namespace apcs {

using Command = std::variant<command::TypeCharacter, command::EraseCharacter, command::ClearLine, command::SubmitLine,
                             command::ChooseGlobal, command::ChooseLocal, command::ArrowMove, command::StaffStep,
                             command::Accept, command::Keep, command::Back, command::ToggleKeyFrames, command::Zoom,
                             command::ToggleGhost,
                             command::ToggleTangents, command::ToggleLawGraph, command::PinReference,
                             command::ChoosePoint,
                             command::OpenValueField, command::OpenWaypoints, command::InsertPoint,
                             command::DeletePoint, command::MovePoint, command::Undo, command::Yes,
                             command::No, command::Continue, command::ShowHelp, command::SavePicture, command::Quit,
                             command::StopAnimation, command::Pause, command::Replay, command::StepFrame>;

} // namespace apcs
