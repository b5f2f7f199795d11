#include "apcs/editor/path_document.h"

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

PathDocument::StaffSet PathDocument::set_staff(ControlRegion region, const StaffValues& staff)
{
    StaffSet set{apply_staff_to_region(m_points, region, staff), false};
    set.changed = staff_runs(m_points, region) != set.runs_before;
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
