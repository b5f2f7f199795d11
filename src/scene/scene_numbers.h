#pragma once

namespace apcs {

// Whether `value` is at most `limit` once the round-off of numbers up to `magnitude` (the largest
// |coordinate| or distance `value` was computed from) is forgiven: a joint drawn exactly TOLERANCE
// apart in decimal, or a RIGID part of no size, is not refused over its last bits (issue 45).
bool at_most_within_round_off(double value, double limit, double magnitude);

} // namespace apcs
