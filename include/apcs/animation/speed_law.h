#pragma once

#include <optional>
#include <string_view>

namespace apcs {

// Distance-time functions f: [0, 1] → [0, 1] with f(0) = 0, f(1) = 1, monotone (slides of seed 004
// and the 2003 paper): linear t, ease-in 1−cos(πt/2), ease-out sin(πt/2), ease-in-out (1−cos πt)/2,
// sqrt √t ("parabolic") and square t² ("inverse parabolic").
enum class SpeedLaw { linear, ease_in, ease_out, ease_in_out, sqrt, square };

// Arguments outside [0, 1] are clamped.
double distance_fraction(SpeedLaw law, double time_fraction);

std::optional<SpeedLaw> speed_law_from_name(std::string_view name);
std::string_view speed_law_name(SpeedLaw law);

// The thesis' acceleration law (Ch. 3.1, SPEC §4.3): the fraction of a span's length reached at
// time fraction tau, (1−|a|)·tau + |a|·w(tau), with w = ease-out for a < 0 (deceleration) and
// ease-in for a > 0. `acceleration` is clamped to [−1, 1].
double acceleration_distance_fraction(double tau, double acceleration);

} // namespace apcs
