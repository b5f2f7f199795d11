#include "apcs/playback/animation_player.h"

// The player's chart: every command the key map lets through in each of its leaves is a row here
// (tests/input/charts.test.cpp walks them; the chart prints itself to tests/golden/session_chart.txt,
// below the session's). The clock's ticks are not commands: tick() moves the frames, and stops at
// the last.
namespace apcs {

namespace {

using State = AnimationPlayer::State;

} // namespace

const AnimationPlayer::PlayerChart& AnimationPlayer::chart() { return PlayerChart::once<&make_chart>(); }

AnimationPlayer::PlayerChart AnimationPlayer::make_chart()
{
    using P = AnimationPlayer;
    using C = const Command&;
    std::vector<PlayerChart::StateInfo> states = {
        {State::player, "player", std::nullopt, KeyContext::any_key_graphics},
        {State::showing, "showing", State::player, KeyContext::animation, "step 6: animation"},
        {State::running, "running", State::showing},
        {State::paused, "paused", State::showing},
        {State::stopped, "stopped", State::player, {}, "step 6: animation done"},
        {State::overlaid, "overlaid", State::player, {}, "step 6: all frames"},
    };
    std::vector<PlayerChart::Row> rows = {
        {State::showing, on<command::StopAnimation>, {}, nullptr, "the frame shown stays",
         [](P& p, C) { p.m_mode = Stopped{}; }, State::stopped},
        {State::running, on<command::Pause>, {}, nullptr, "paused at the frame shown",
         [](P& p, C) { p.m_mode = Showing{true}; }, State::paused},
        {State::paused, on<command::Pause>, {}, nullptr, "going on", [](P& p, C) { p.m_mode = Showing{false}; },
         State::running},
        {State::showing, on<command::Replay>, {}, nullptr, "from the first frame",
         [](P& p, C) {
             p.m_frame = 0;
             p.m_mode = Showing{false};
         },
         State::running},
        {State::showing, on<command::StepFrame>, {}, nullptr, "the frame before or after",
         [](P& p, C c) { p.step_frame(std::get<command::StepFrame>(c).by); }, State::paused},
        {State::stopped, on<command::Continue>, {}, nullptr, "all frames overlaid, logged",
         [](P& p, C) { p.overlay_all_frames(); }, State::overlaid},
        {State::overlaid, on<command::Continue>, {}, nullptr, "the session ends",
         [](P& p, C) { p.m_finished = true; }},
    };
    return PlayerChart(std::move(states), std::move(rows));
}

} // namespace apcs
