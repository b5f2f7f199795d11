#include "apcs/animation/control_region.h"

#include "apcs/animation/input_limits.h"

namespace apcs {

void apply_staff_to_region(ControlPoints& points, ControlRegion region, const StaffValues& staff)
{
    const bool whole = region.is_whole(points);
    for (std::size_t k = region.first; k <= region.last && k < points.size(); ++k) {
        for (const StaffLine line : {StaffLine::tension, StaffLine::continuity, StaffLine::bias})
            points[k].staff[line] = limits::staff_value.clamp(staff[line]);
        if (k < region.last || whole)
            points[k].staff.acceleration = limits::staff_value.clamp(staff.acceleration);
    }
}

} // namespace apcs
