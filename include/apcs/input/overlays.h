#pragma once

#include "apcs/input/command.h"
#include "apcs/input/key_map.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace apcs {

// What any step may be asked (SPEC §3, §7.3): its help screen, a picture of the screen, and
// ending the program. The help screen and the quit question are laid over the step, which stays
// as it was underneath; the session and a scene's player (apcs play) share them.
namespace overlay {
// The keys of the step underneath, listed until any key closes the screen.
struct HelpScreen {
    KeyContext keys;
    // At a text prompt, the answer an empty line takes there (the help names it); else empty.
    std::string empty_answer;
};
// "Quit without saving this path ? (Y/N)" after q on the path screen, "Quit APCS ? (Y/N)" after
// Esc on an empty text prompt (words.h holds both): Y quits; N, Enter or Esc goes back to
// the step as it was; other keys do nothing.
struct QuitQuestion {
    std::string_view question;
};
} // namespace overlay

// What a command meant to the overlays: nothing (it is the step's), done, or what the program
// must do for them.
enum class OverlayAnswer { step_command, handled, save_picture, quit };

class Overlays {
public:
    // The keys in force: the open overlay's, else the step's (`step`).
    KeyContext key_context(KeyContext step) const;
    // `command` as read in `context` (key_context's), for a program whose steps keep nothing
    // unsaved (apcs play: q quits at once; the session's chart has rows of its own). Opens and
    // closes the help.
    OverlayAnswer handle(KeyContext context, const Command& command);
    // The help screen for `keys` (a prompt's answer "?" asks for it too).
    void open_help(KeyContext keys, std::string empty_answer)
    {
        m_open = overlay::HelpScreen{keys, std::move(empty_answer)};
        ++m_revision;
    }
    // The quit question in the words `question` (a words.h constant: the view outlives the
    // overlay): the session's chart asks it for q on the path screen and Esc on an empty prompt.
    void ask_quit(std::string_view question)
    {
        m_open = overlay::QuitQuestion{question};
        ++m_revision;
    }
    void close()
    {
        if (m_open)
            ++m_revision;
        m_open.reset();
    }
    // Advanced by every overlay opened or closed.
    std::uint64_t revision() const { return m_revision; }

    const overlay::HelpScreen* help() const;
    const overlay::QuitQuestion* quit_question() const;
    bool asking_quit() const { return quit_question() != nullptr; }

private:
    OverlayAnswer answer_open(const Command& command);

    std::optional<std::variant<overlay::HelpScreen, overlay::QuitQuestion>> m_open;
    std::uint64_t m_revision = 0;
};

} // namespace apcs
