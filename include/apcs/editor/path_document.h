#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/control_region.h"
#include "apcs/animation/path_change.h"
#include "apcs/animation/waypoint_change.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
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

// Turns the points after a change back into those before it: the ghost's path (SPEC §7.2.1: the
// curve before the last change, dotted).
using PointsBack = std::function<void(ControlPoints&)>;

// What the document's changes since a revision did together: the range they cover (path_change.h)
// and the way back over all of them.
struct ChangesTaken {
    PathChange change;
    PointsBack back;
};

// The path being shaped, the one copy of it: its control points, where each came from in the path
// file, every edit since it was opened (oldest first) and a revision that every change advances.
// It records its own edits: a staff key, a waypoint edit and an undo each change the points, join
// (or leave) the history and are kept as a change for its picture (PathPicture), which takes them
// when it is next read. Both editors change it in place.
class PathDocument {
public:
    // A path as read: point k is the file's point k.
    explicit PathDocument(ControlPoints points);
    PathDocument(ControlPoints points, std::vector<std::size_t> origins);

    const ControlPoints& points() const { return m_points; }
    // Parallel to points() (waypoint_change.h).
    const std::vector<std::size_t>& origins() const { return m_origins; }
    // Advanced by every change.
    std::uint64_t revision() const { return m_revision; }

    // A staff key: the region's points given `staff` (edit.region; edit.points_before is filled
    // here). It is an edit, recorded for undo, when it changed a point or the staff shown
    // (edit.staff, as it was before the key); a step past the end of a line is neither and leaves
    // the revision. Returns the change, none for no edit.
    std::optional<PathChange> set_staff(StaffEdit edit, const StaffValues& staff);
    // A waypoint edit made and recorded; returns what changed.
    PathChange apply(const WaypointChange& change);
    // U: the newest edit taken back and out of the history (there is one); returns it.
    PathEdit undo();

    std::size_t edit_count() const { return m_edits.size(); }
    const std::vector<PathEdit>& edits() const { return m_edits; }

    // The changes after `revision`, taken together and out of the document, for its one picture;
    // none when there are none, or when they are no longer all kept (another reader took them:
    // this one is then made again whole, and the changes kept stay for the reader they are for).
    // The document keeps only what is not taken yet.
    std::optional<ChangesTaken> take_changes(std::uint64_t revision);

private:
    void changed(const PathChange& change, PointsBack back);
    void take_back(const StaffEdit& edit);
    void take_back(const WaypointChange& edit);

    ControlPoints m_points;
    std::vector<std::size_t> m_origins;
    std::uint64_t m_revision = 0;
    std::vector<PathEdit> m_edits;
    // The changes the picture has not taken yet, oldest first: the revision each made.
    struct Untaken {
        std::uint64_t revision = 0;
        PathChange change;
        PointsBack back;
    };
    std::vector<Untaken> m_untaken;
};

} // namespace apcs
