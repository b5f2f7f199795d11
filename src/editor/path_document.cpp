#include "apcs/editor/path_document.h"

#include "apcs/animation/input_limits.h"

#include <cassert>

namespace apcs {

PathDocument::PathDocument(ControlPoints points)
    : m_points(std::move(points))
    , m_origins(file_origins(m_points.size()))
{
}

PathDocument::PathDocument(ControlPoints points, std::vector<std::size_t> origins)
    : m_points(std::move(points))
    , m_origins(std::move(origins))
{
    assert(m_origins.size() == m_points.size());
}

PathChange PathDocument::apply(const WaypointChange& change)
{
    ++m_revision;
    return apply_change(m_points, m_origins, change);
}

PathChange PathDocument::revert(const WaypointChange& change)
{
    ++m_revision;
    return revert_change(m_points, m_origins, change);
}

PathEdit PathDocument::take_last_edit()
{
    assert(!m_edits.empty());
    PathEdit last = std::move(m_edits.back());
    m_edits.pop_back();
    return last;
}

namespace {

// Whether the region's points held, before, what apply_staff_to_region leaves them with: every
// run the staff (clamped to the staff's range), but for the region's last point its own
// acceleration, which stays (no span starts there) unless the region is the whole path. Read from
// the runs alone: a key on 10^6 points does not read them again.
bool held_already(const std::vector<StaffRun>& before, const StaffValues& staff, bool whole)
{
    StaffValues clamped;
    for (const StaffLine line : staff_lines)
        clamped[line] = limits::staff_value.clamp(staff[line]);
    for (std::size_t run = 0; run < before.size(); ++run) {
        StaffValues after = clamped;
        if (run + 1 == before.size() && before[run].count == 1 && !whole)
            after.acceleration = before[run].staff.acceleration;
        if (before[run].staff != after)
            return false;
    }
    return true;
}

} // namespace

PathDocument::StaffSet PathDocument::set_staff(ControlRegion region, const StaffValues& staff)
{
    const bool whole = region.is_whole(m_points);
    StaffSet set{apply_staff_to_region(m_points, region, staff), false};
    set.changed = !held_already(set.runs_before, staff, whole);
    if (set.changed)
        ++m_revision;
    return set;
}

void PathDocument::restore_staff(ControlRegion region, const std::vector<StaffRun>& runs)
{
    ++m_revision;
    restore_staff_runs(m_points, region, runs);
}

} // namespace apcs
