#pragma once

#include "apcs/base/large_array.h"
#include "apcs/geometry/vec3.h"

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

namespace apcs {

// The four lines of the staff (thesis fig. 3.1.5), in the order the session takes them.
enum class StaffLine { tension, continuity, bias, acceleration };

inline constexpr std::array<StaffLine, 4> staff_lines{StaffLine::tension, StaffLine::continuity, StaffLine::bias,
                                                      StaffLine::acceleration};

// "TENSION", "CONTINUITY", "BIAS", "ACCELERATION": the staff's labels, the log's words and the
// seven-column .dat file's column order after x y z.
constexpr std::string_view staff_line_name(StaffLine line)
{
    constexpr std::array<std::string_view, 4> names{"TENSION", "CONTINUITY", "BIAS", "ACCELERATION"};
    return names[static_cast<std::size_t>(line)];
}

// Acceleration is the last line; the line after it is itself.
constexpr bool is_last_staff_line(StaffLine line) { return line == StaffLine::acceleration; }
constexpr StaffLine next_staff_line(StaffLine line)
{
    return is_last_staff_line(line) ? line : static_cast<StaffLine>(static_cast<int>(line) + 1);
}

// The four-line staff of thesis fig. 3.1.5. Every value lies in [-1, 1] (limits::staff_value): the
// readers of files and options refuse others; the core clamps what reaches it.
struct StaffValues {
    double tension = 0.0;
    double continuity = 0.0;
    double bias = 0.0;
    // The acceleration of the span that starts at this control point (SPEC §2.1).
    double acceleration = 0.0;

    constexpr double& operator[](StaffLine line)
    {
        switch (line) {
        case StaffLine::tension: return tension;
        case StaffLine::continuity: return continuity;
        case StaffLine::bias: return bias;
        case StaffLine::acceleration: break;
        }
        return acceleration;
    }
    constexpr double operator[](StaffLine line) const { return const_cast<StaffValues&>(*this)[line]; }

    friend constexpr bool operator==(const StaffValues&, const StaffValues&) = default;
};

struct ControlPoint {
    Vec3 position;
    StaffValues staff;

    friend constexpr bool operator==(const ControlPoint&, const ControlPoint&) = default;
};

// Slopes S0 and S1 in [0, 1] that scale the end tangents (thesis "DS[0], DD[N]").
struct EndSlopes {
    double start = 1.0;
    double end = 1.0;
};

// A motion path: at least two control points, first = KEY1 position, last = KEY2 position.
using ControlPoints = std::vector<ControlPoint, LargeArrayAllocator<ControlPoint>>;

} // namespace apcs
