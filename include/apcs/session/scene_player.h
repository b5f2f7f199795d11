#pragma once

#include "apcs/session/animation_player.h"
#include "apcs/session/interactive_program.h"
#include "apcs/session/overlays.h"

#include <functional>
#include <string>

namespace apcs {

// Writes the screen shown as a picture (P) and says what happened, for the message line.
using PictureSaver = std::function<std::string(const GraphicsScreen& screen)>;

// apcs play as a program of the one terminal loop: the player's frames every `delay_ms`, Esc,
// Space and R as in the session's animation, then all frames overlaid until a key ends it; q ends
// it at once (every file is already written: no question), ? shows the keys, and the frames wait
// until a key closes the help; P hands the screen to `save_picture`.
class ScenePlayer final : public InteractiveProgram {
public:
    ScenePlayer(AnimationPlayer& player, int delay_ms, PictureSaver save_picture);

    void handle(const KeyEvent& event) override;
    void tick() override { m_player.tick(); }
    bool finished() const override { return m_finished; }
    bool animating() const override { return m_player.playing() && m_overlays.help() == nullptr; }
    int delay_ms() const override { return m_delay_ms; }
    SessionScreen screen() const override;

private:
    AnimationPlayer& m_player;
    int m_delay_ms;
    PictureSaver m_save_picture;
    Overlays m_overlays;
    bool m_finished = false;
};

} // namespace apcs
