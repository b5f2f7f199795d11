#pragma once

#include "apcs/session/command.h"
#include "apcs/session/key_map.h"

#include <optional>
#include <variant>

namespace apcs {

// What any step may be asked (SPEC §3, §7.3): its help screen, a picture of the screen, and
// ending the program. The help screen and the quit question are laid over the step, which stays
// as it was underneath; the session and a scene's player (apcs play) share them.
namespace overlay {
// The keys of the step underneath, listed until any key closes the screen.
struct HelpScreen {
    KeyContext keys;
};
// "Quit without saving this path ? (Y/N)": Y quits, N or Enter goes back, other keys do nothing.
struct QuitQuestion {};
} // namespace overlay

// Quit at once, or ask first (only an unsaved path is worth the question).
enum class QuitAsks { at_once, question_first };

// What a command meant to the overlays: nothing (it is the step's), done, or what the program
// must do for them.
enum class OverlayAnswer { step_command, handled, save_picture, quit };

class Overlays {
public:
    // The keys in force: the open overlay's, else the step's (`step`).
    KeyContext key_context(KeyContext step) const;
    // `command` as read in `context` (key_context's). Opens and closes the overlays.
    OverlayAnswer handle(KeyContext context, const Command& command, QuitAsks quit);
    // The help screen for `keys` (a prompt's answer "?" asks for it too).
    void open_help(KeyContext keys) { m_open = overlay::HelpScreen{keys}; }

    const overlay::HelpScreen* help() const;
    bool asking_quit() const { return m_open && std::holds_alternative<overlay::QuitQuestion>(*m_open); }

private:
    OverlayAnswer answer_open(const Command& command);

    std::optional<std::variant<overlay::HelpScreen, overlay::QuitQuestion>> m_open;
};

} // namespace apcs
