#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/control_region.h"
#include "apcs/animation/path_change.h"
#include "apcs/animation/waypoint_change.h"

#include <cstddef>
#include <cstdint>
#include <variant>
#include <vector>

namespace apcs {

// A key on the staff, kept for undo: the region and the line it was typed on, the staff shown and
// the line's value when the line became active, and the region's points' values before it.
struct StaffEdit {
    ControlRegion region;
    StaffLine line = StaffLine::tension;
    StaffValues staff;
    double line_start_value = 0.0;
    std::vector<StaffRun> points_before;
};

// One change of the path for undo (U): a staff key or a waypoint edit.
using PathEdit = std::variant<StaffEdit, WaypointChange>;

// The path being shaped, the one copy of it: its control points, where each came from in the path
// file, every edit since it was opened (oldest first) and a revision that every change of the
// points advances. Both editors change it in place; its picture (PathPicture) reads it.
class PathDocument {
public:
    // A path as read: point k is the file's point k.
    explicit PathDocument(ControlPoints points);
    PathDocument(ControlPoints points, std::vector<std::size_t> origins);

    const ControlPoints& points() const { return m_points; }
    // Parallel to points() (waypoint_change.h).
    const std::vector<std::size_t>& origins() const { return m_origins; }
    // Advanced by every change of the points.
    std::uint64_t revision() const { return m_revision; }

    // A waypoint edit made or taken back; returns what changed, for the picture to follow.
    PathChange apply(const WaypointChange& change);
    PathChange revert(const WaypointChange& change);
    // New staff values for a region's points: the region's runs as they were, and whether any
    // point changed (a step past the end of a line changes none, and leaves the revision).
    struct StaffSet {
        std::vector<StaffRun> runs_before;
        bool changed = false;
    };
    StaffSet set_staff(ControlRegion region, const StaffValues& staff);
    // A region's runs put back as they were.
    void restore_staff(ControlRegion region, const std::vector<StaffRun>& runs);

    // The undo history: edits are recorded once made, and taken back newest first.
    void record(PathEdit edit) { m_edits.push_back(std::move(edit)); }
    std::size_t edit_count() const { return m_edits.size(); }
    const std::vector<PathEdit>& edits() const { return m_edits; }
    // The newest edit, out of the history (there is one).
    PathEdit take_last_edit();

private:
    ControlPoints m_points;
    std::vector<std::size_t> m_origins;
    std::uint64_t m_revision = 0;
    std::vector<PathEdit> m_edits;
};

} // namespace apcs
