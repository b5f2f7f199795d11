#include "apcs/input/overlays.h"

#include "apcs/base/overloaded.h"

namespace apcs {

KeyContext Overlays::key_context(KeyContext step) const
{
    if (!m_open)
        return step;
    return std::holds_alternative<overlay::QuitQuestion>(*m_open) ? KeyContext::quit_question : KeyContext::help_screen;
}

const overlay::HelpScreen* Overlays::help() const
{
    return m_open ? std::get_if<overlay::HelpScreen>(&*m_open) : nullptr;
}

const overlay::QuitQuestion* Overlays::quit_question() const
{
    return m_open ? std::get_if<overlay::QuitQuestion>(&*m_open) : nullptr;
}

OverlayAnswer Overlays::handle(KeyContext context, const Command& command)
{
    if (m_open)
        return answer_open(command);
    return std::visit(Overloaded{[&](const command::ShowHelp&) {
                                     open_help(context, {});
                                     return OverlayAnswer::handled;
                                 },
                                 [](const command::SavePicture&) { return OverlayAnswer::save_picture; },
                                 [](const command::Quit&) { return OverlayAnswer::quit; },
                                 // Every other command is the step's: the overlays take only these three.
                                 [](const auto&) { return OverlayAnswer::step_command; }},
                      command);
}

// Any key closes the help screen; the quit question quits on Y alone (the key map lets only Y, N,
// Enter and Esc through to it).
OverlayAnswer Overlays::answer_open(const Command& command)
{
    const bool quitting = asking_quit() && std::holds_alternative<command::Yes>(command);
    close();
    return quitting ? OverlayAnswer::quit : OverlayAnswer::handled;
}

} // namespace apcs
