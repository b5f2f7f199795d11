#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/path_change.h"

#include <cstddef>
#include <vector>

namespace apcs {

// Where a control point of an edited path came from: its index among the path file's points, or
// new_point for one the waypoint editor inserted. The file's comments stay with their points.
inline constexpr std::size_t new_point = static_cast<std::size_t>(-1);

// The origins of a path as read: point k is the file's point k.
std::vector<std::size_t> file_origins(std::size_t point_count);

// Choosing `by` control points on from `index` among `count` (Tab, Shift-Tab): past the last comes
// the first, before the first the last.
std::size_t wrapped_point(std::size_t index, int by, std::size_t count);

// One edit of a path's control points in the waypoint editor. Each can be reverted exactly, so
// that undo (U) and leaving the editor with Esc take changes back in reverse order.
struct WaypointChange {
    enum class Kind { insert, remove, move };
    Kind kind = Kind::move;
    std::size_t index = 0;  // the point inserted (its new index), removed or moved
    ControlPoint point;     // the point inserted or removed
    std::size_t origin = new_point; // the removed point's origin
    Vec3 offset;            // a move's displacement
};

// `origins` runs parallel to `points`; both change together. An index outside the points is a
// programming error (asserted). Returns the points changed, for the path's picture to follow.
PathChange apply_change(ControlPoints& points, std::vector<std::size_t>& origins, const WaypointChange& change);
PathChange revert_change(ControlPoints& points, std::vector<std::size_t>& origins, const WaypointChange& change);
// The same on points whose origins nobody keeps (a copy taken back or forward over an edit: the
// ghost's path).
void apply_change(ControlPoints& points, const WaypointChange& change);
void revert_change(ControlPoints& points, const WaypointChange& change);

} // namespace apcs
