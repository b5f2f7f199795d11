#pragma once

#include "apcs/geometry/vec3.h"

#include <vector>

namespace apcs {

// The four-line staff of thesis fig. 3.1.5. Every value lies in [-1, 1].
struct StaffValues {
    double tension = 0.0;
    double continuity = 0.0;
    double bias = 0.0;
    // The acceleration of the span that starts at this control point (SPEC §2.1).
    double acceleration = 0.0;

    friend constexpr bool operator==(const StaffValues&, const StaffValues&) = default;
};

struct ControlPoint {
    Vec3 position;
    StaffValues staff;
};

// Slopes S0 and S1 in [0, 1] that scale the end tangents (thesis "DS[0], DD[N]").
struct EndSlopes {
    double start = 1.0;
    double end = 1.0;
};

// A motion path: at least two control points, first = KEY1 position, last = KEY2 position.
using ControlPoints = std::vector<ControlPoint>;

} // namespace apcs
