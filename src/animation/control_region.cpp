#include "apcs/animation/control_region.h"

#include "apcs/animation/input_limits.h"

#include <algorithm>
#include <array>

namespace apcs {

namespace {

// The lines that shape the tangents, and so the segments.
constexpr std::array shape_lines{StaffLine::tension, StaffLine::continuity, StaffLine::bias};

} // namespace

void apply_staff_to_region(ControlPoints& points, ControlRegion region, const StaffValues& staff)
{
    const bool whole = region.is_whole(points);
    for (std::size_t k = region.first; k <= region.last && k < points.size(); ++k) {
        for (const StaffLine line : shape_lines)
            points[k].staff[line] = limits::staff_value.clamp(staff[line]);
        if (k < region.last || whole)
            points[k].staff.acceleration = limits::staff_value.clamp(staff.acceleration);
    }
}

std::vector<StaffRun> staff_runs(const ControlPoints& points, ControlRegion region)
{
    std::vector<StaffRun> runs;
    for (std::size_t k = region.first; k <= region.last && k < points.size(); ++k) {
        if (!runs.empty() && runs.back().staff == points[k].staff)
            ++runs.back().count;
        else
            runs.push_back({1, points[k].staff});
    }
    return runs;
}

void restore_staff_runs(ControlPoints& points, ControlRegion region, const std::vector<StaffRun>& runs)
{
    std::size_t k = region.first;
    for (const StaffRun& run : runs)
        for (std::size_t i = 0; i < run.count && k < points.size(); ++i, ++k)
            points[k].staff = run.staff;
}

bool runs_change_shape(const std::vector<StaffRun>& runs, const StaffValues& shape)
{
    const auto clamped = [](const StaffValues& staff, StaffLine line) { return limits::staff_value.clamp(staff[line]); };
    return std::any_of(runs.begin(), runs.end(), [&](const StaffRun& run) {
        return std::any_of(shape_lines.begin(), shape_lines.end(),
                           [&](StaffLine line) { return clamped(run.staff, line) != clamped(shape, line); });
    });
}

} // namespace apcs
