#include "apcs/playback/scene_player.h"

#include <utility>

namespace apcs {

ScenePlayer::ScenePlayer(AnimationPlayer& player, int delay_ms, PictureSaver save_picture)
    : m_player(player)
    , m_delay_ms(delay_ms)
    , m_save_picture(std::move(save_picture))
{
}

void ScenePlayer::handle(const KeyEvent& event)
{
    take(event);
    ++m_revision;
}

void ScenePlayer::take(const KeyEvent& event)
{
    const KeyContext keys = m_overlays.key_context(m_player.key_context());
    const std::optional<Command> command = command_for(keys, event);
    if (!command)
        return;
    switch (m_overlays.handle(keys, *command)) {
    case OverlayAnswer::step_command:
        m_finished = m_player.update(*command) == AnimationPlayer::Outcome::finished;
        return;
    case OverlayAnswer::handled: return;
    case OverlayAnswer::save_picture: return m_player.show_notice(m_save_picture(m_player.picture()));
    case OverlayAnswer::quit: m_finished = true; return;
    }
}

ProgramScreen ScenePlayer::screen() const
{
    if (const overlay::HelpScreen* help = m_overlays.help())
        return {false, key_help_screen("playing a scene", help->keys), {}};
    return {true, {}, m_player.view()};
}

} // namespace apcs
