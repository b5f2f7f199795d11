#pragma once

#include "apcs/playback/animation_player.h"
#include "apcs/input/interactive_program.h"
#include "apcs/input/overlays.h"

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
    void tick() override
    {
        m_player.tick();
        ++m_revision;
    }
    bool finished() const override { return m_finished; }
    bool animating() const override { return m_player.playing() && m_overlays.help() == nullptr; }
    int delay_ms() const override { return m_delay_ms; }
    ProgramScreen screen() const override;
    // Every key and tick may change what is shown.
    std::uint64_t screen_revision() const override { return m_revision; }

private:
    void take(const KeyEvent& event);

    AnimationPlayer& m_player;
    int m_delay_ms;
    PictureSaver m_save_picture;
    Overlays m_overlays;
    bool m_finished = false;
    std::uint64_t m_revision = 0;
};

} // namespace apcs
