#pragma once

#include <algorithm>

// The ranges every input of APCS must lie in, whether it comes from the command line, a file or
// a session prompt: one table, so the three readers cannot disagree.
namespace apcs::limits {

struct Range {
    double min;
    double max;

    constexpr bool contains(double value) const { return value >= min && value <= max; }
    constexpr double clamp(double value) const { return std::clamp(value, min, max); }
};

// Tension, continuity, bias and acceleration (thesis fig. 3.1.5).
inline constexpr Range staff_value{-1.0, 1.0};
// DS[0] and DD[N] (thesis fig. 4.2.3: "ranged from 0 to 1").
inline constexpr Range end_slope{0.0, 1.0};
// THETA and PHI in degrees; any angle is meaningful, the bound only keeps trigonometry exact.
inline constexpr Range view_degrees{-1e6, 1e6};
// Milliseconds between animation frames.
inline constexpr Range delay_ms{0, 60000};
// Milliseconds between the keys of a paced replay (--pace).
inline constexpr Range pace_ms{1, 60000};
// Curve samples per KB segment.
inline constexpr Range samples_per_segment{1, 100000};
// In-between frames M.
inline constexpr Range inbetween_count{0, 100000};
// Frame intervals T of `apcs inbetween --frames` (frames 0 … T).
inline constexpr Range frame_intervals{1, 100000};
// The staff's step per key.
inline constexpr Range staff_step{0.001, 2.0};

} // namespace apcs::limits
