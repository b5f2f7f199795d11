#pragma once

#include "apcs/formats/physical_key.h"

namespace apcs {

// A key as the session reads it: a physical key (physical_key.h), or a character typed.
struct KeyEvent {
    Key key = Key::character;
    char32_t character = 0;

    static KeyEvent of(Key key) { return {key, 0}; }
    static KeyEvent typed(char32_t character) { return {Key::character, character}; }
    bool operator==(const KeyEvent&) const = default;
};

} // namespace apcs
