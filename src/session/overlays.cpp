#include "apcs/session/overlays.h"

#include "apcs/session/overloaded.h"

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

OverlayAnswer Overlays::handle(KeyContext context, const Command& command, QuitAsks quit)
{
    if (m_open)
        return answer_open(command);
    return std::visit(Overloaded{[&](const command::ShowHelp&) {
                                     m_open = overlay::HelpScreen{context};
                                     return OverlayAnswer::handled;
                                 },
                                 [](const command::SavePicture&) { return OverlayAnswer::save_picture; },
                                 [&](const command::Quit&) {
                                     if (quit == QuitAsks::at_once)
                                         return OverlayAnswer::quit;
                                     m_open = overlay::QuitQuestion{};
                                     return OverlayAnswer::handled;
                                 },
                                 // Every other command is the step's: the overlays take only these three.
                                 [](const auto&) { return OverlayAnswer::step_command; }},
                      command);
}

// Any key closes the help screen; the quit question quits on Y alone.
OverlayAnswer Overlays::answer_open(const Command& command)
{
    const bool quitting = asking_quit() && std::holds_alternative<command::Yes>(command);
    m_open.reset();
    return quitting ? OverlayAnswer::quit : OverlayAnswer::handled;
}

} // namespace apcs
