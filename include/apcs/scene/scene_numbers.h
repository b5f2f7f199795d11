#pragma once

#include "apcs/geometry/vec3.h"

#include <string>
#include <utility>

namespace apcs {

// Whether `value` is at most `limit` once the round-off of numbers up to `magnitude` (the largest
// |coordinate| or distance `value` was computed from) is forgiven: a joint drawn exactly TOLERANCE
// apart in decimal, or a RIGID part of no size, is not refused over its last bits (issue 45).
bool at_most_within_round_off(double value, double limit, double magnitude);

// A number of a scene message: `digits` significant digits (6 unless said), '.' as the decimal
// point whatever the locale, -0 as 0: "11.3", not 11.300000000000001.
std::string scene_number(double value, int digits = 6);

// Two numbers a message compares (a distance and its limit, two TOLERANCE values): scene_number's
// six digits, more when six would show two different values alike.
std::pair<std::string, std::string> scene_numbers(double a, double b);

// "(x, y, z)" in scene_number's digits.
std::string scene_point(const Vec3& point);

} // namespace apcs
