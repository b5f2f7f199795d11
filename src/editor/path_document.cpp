#include "apcs/editor/path_document.h"

#include "apcs/animation/input_limits.h"

#include <algorithm>
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

void PathDocument::changed(const PathChange& change, PointsBack back)
{
    ++m_revision;
    m_untaken.push_back({m_revision, change, std::move(back)});
}

std::optional<ChangesTaken> PathDocument::take_changes(std::uint64_t revision)
{
    if (revision == m_revision)
        return std::nullopt;
    // Every change is kept until taken, one revision each: older ones were another reader's.
    const auto first = std::find_if(m_untaken.begin(), m_untaken.end(),
                                    [revision](const Untaken& untaken) { return untaken.revision == revision + 1; });
    if (first == m_untaken.end())
        return std::nullopt;
    std::optional<ChangesTaken> taken;
    for (auto next = first; next != m_untaken.end(); ++next) {
        if (!taken) {
            taken = ChangesTaken{next->change, std::move(next->back)};
            continue;
        }
        taken->change = combined(taken->change, next->change);
        // Back over the newest change first.
        taken->back = [newer = std::move(next->back), older = std::move(taken->back)](ControlPoints& points) {
            newer(points);
            older(points);
        };
    }
    m_untaken.clear();
    return taken;
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

// The ghost's way back over a staff change: the region's runs as they were.
PointsBack staff_runs_back(ControlRegion region, std::vector<StaffRun> runs)
{
    return [region, runs = std::move(runs)](ControlPoints& points) { restore_staff_runs(points, region, runs); };
}

// A change of the region's staff values: its segments change unless only accelerations did.
PathChange staff_change(ControlRegion region, const std::vector<StaffRun>& runs, const StaffValues& shape)
{
    const std::size_t count = region.last - region.first + 1;
    const PathChange::What what =
        runs_change_shape(runs, shape) ? PathChange::What::staff : PathChange::What::accelerations;
    return {region.first, count, count, what};
}

} // namespace

std::optional<PathChange> PathDocument::set_staff(StaffEdit edit, const StaffValues& staff)
{
    const bool whole = edit.region.is_whole(m_points);
    edit.points_before = apply_staff_to_region(m_points, edit.region, staff);
    if (edit.staff == staff && held_already(edit.points_before, staff, whole))
        return std::nullopt;
    const PathChange change = staff_change(edit.region, edit.points_before, staff);
    changed(change, staff_runs_back(edit.region, edit.points_before));
    m_edits.push_back(std::move(edit));
    return change;
}

PathChange PathDocument::apply(const WaypointChange& change)
{
    const PathChange made = apply_change(m_points, m_origins, change);
    changed(made, [change](ControlPoints& points) { revert_change(points, change); });
    m_edits.push_back(change);
    return made;
}

PathEdit PathDocument::undo()
{
    assert(!m_edits.empty());
    PathEdit last = std::move(m_edits.back());
    m_edits.pop_back();
    std::visit([this](const auto& edit) { take_back(edit); }, last);
    return last;
}

void PathDocument::take_back(const StaffEdit& edit)
{
    const PathChange change = staff_change(edit.region, edit.points_before, m_points[edit.region.first].staff);
    // The ghost: the path with the edit, as it was before U.
    PointsBack back = staff_runs_back(edit.region, staff_runs(m_points, edit.region));
    restore_staff_runs(m_points, edit.region, edit.points_before);
    changed(change, std::move(back));
}

void PathDocument::take_back(const WaypointChange& edit)
{
    const PathChange change = revert_change(m_points, m_origins, edit);
    changed(change, [edit](ControlPoints& points) { apply_change(points, edit); });
}

} // namespace apcs
