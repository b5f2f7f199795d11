#pragma once

namespace apcs {

// How a replay on a terminal plays its script (--pace): at once, one key every `milliseconds`,
// or one key each time the presenter presses Space. A TEXT line is one step, played whole.
struct ReplayPace {
    enum class Kind { at_once, every, on_space };
    Kind kind = Kind::at_once;
    int milliseconds = 0;
};

} // namespace apcs
