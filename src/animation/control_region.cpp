#include "apcs/animation/control_region.h"

#include "apcs/animation/input_limits.h"
#include "apcs/base/parallel_work.h"

#include <algorithm>
#include <array>

namespace apcs {

namespace {

// The lines that shape the tangents, and so the segments.
constexpr std::array shape_lines{StaffLine::tension, StaffLine::continuity, StaffLine::bias};

void add_to_runs(std::vector<StaffRun>& runs, const StaffRun& run)
{
    if (!runs.empty() && runs.back().staff == run.staff)
        runs.back().count += run.count;
    else
        runs.push_back(run);
}

} // namespace

// One pass that reads each point's values, then writes them, in two halves on two cores: on a
// path of 10^6 control points a key's time is passes over the points.
std::vector<StaffRun> apply_staff_to_region(ControlPoints& points, ControlRegion region, const StaffValues& staff)
{
    if (region.first >= points.size() || region.first > region.last)
        return {};
    const bool whole = region.is_whole(points);
    StaffValues clamped;
    for (const StaffLine line : staff_lines)
        clamped[line] = limits::staff_value.clamp(staff[line]);
    const std::size_t end = std::min(region.last + 1, points.size());
    std::array<std::vector<StaffRun>, 2> halves;
    split_across_cores(end - region.first, 1 << 16, [&](std::size_t from, std::size_t to) {
        std::vector<StaffRun> before;
        for (std::size_t k = region.first + from; k < region.first + to; ++k) {
            StaffValues& values = points[k].staff;
            add_to_runs(before, {1, values});
            const double acceleration = k < region.last || whole ? clamped.acceleration : values.acceleration;
            values = clamped;
            values.acceleration = acceleration;
        }
        halves[from == 0 ? 0 : 1] = std::move(before);
    });
    std::vector<StaffRun> before = std::move(halves[0]);
    for (const StaffRun& run : halves[1])
        add_to_runs(before, run);
    return before;
}

std::vector<StaffRun> staff_runs(const ControlPoints& points, ControlRegion region)
{
    std::vector<StaffRun> runs;
    for (std::size_t k = region.first; k <= region.last && k < points.size(); ++k)
        add_to_runs(runs, {1, points[k].staff});
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
