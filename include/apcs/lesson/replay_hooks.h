#pragma once

#include "apcs/raster/session_screen.h"

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
};

} // namespace apcs
