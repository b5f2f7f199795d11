#pragma once

// Small helpers shared by the session's source files (not part of the public interface).

#include "apcs/animation/control_point.h"
#include "apcs/session/key_event.h"

#include <algorithm>
#include <cmath>

namespace apcs::session_keys {

inline bool is_yes(const KeyEvent& event)
{
    return event.key == Key::character && (event.character == U'Y' || event.character == U'y');
}

inline bool is_character(const KeyEvent& event, char32_t a, char32_t b = 0)
{
    return event.key == Key::character && (event.character == a || (b != 0 && event.character == b));
}

inline double snapped(double value)
{
    // Keys add multiples of the step; rounding to 1e-9 keeps repeated steps from drifting.
    return std::clamp(std::round(value * 1e9) / 1e9, -1.0, 1.0);
}

inline double& staff_value(StaffValues& staff, int line)
{
    switch (line) {
    case 0: return staff.tension;
    case 1: return staff.continuity;
    case 2: return staff.bias;
    default: return staff.acceleration;
    }
}

} // namespace apcs::session_keys
