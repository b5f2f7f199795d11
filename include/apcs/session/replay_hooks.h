#pragma once

#include "apcs/session/goal_check.h"
#include "apcs/session/session_settings.h"

#include <cstddef>
#include <functional>

namespace apcs {

// What a replay of a key script tells the program that runs it, as it plays.
struct ReplayHooks {
    // Caption `index` of the script is reached: `shown` is the screen a paced replay shows it over,
    // the caption laid on (with_caption). Called once per caption, in the script's order, when the
    // session has played the keys before it and is neither splitting nor animating (the moment the
    // headless replay reaches it too). --handout writes its pages here.
    std::function<void(std::size_t index, const SessionScreen& shown)> caption_reached;
    // How far the session is from goal `index` of the script (GOAL lines, script_goal.h). A replay
    // on a terminal that reaches a goal asks this after every key the student types, until it
    // holds; without it, goals are passed over.
    std::function<GoalProgress(std::size_t index)> goal_progress;
};

} // namespace apcs
