#pragma once

#include "apcs/animation/control_point.h"

#include <cstddef>
#include <vector>

namespace apcs {

// The control points one staff adjusts (thesis Scan_Control_Point): under global control the whole
// path, under local control the run the animator picked, first < last. Indices from 0.
struct ControlRegion {
    std::size_t first = 0;
    std::size_t last = 0;

    static ControlRegion whole(const ControlPoints& points) { return {0, points.empty() ? 0 : points.size() - 1}; }
    bool is_whole(const ControlPoints& points) const { return first == 0 && last + 1 == points.size(); }
    bool contains(std::size_t point) const { return point >= first && point <= last; }
    friend bool operator==(const ControlRegion&, const ControlRegion&) = default;
};

// The staff values of a region's control points, run-length encoded (a run of equal values is one
// entry), so that undoing a key on a whole path of 10^6 points of one value keeps one entry.
struct StaffRun {
    std::size_t count = 0;
    StaffValues staff;
    friend bool operator==(const StaffRun&, const StaffRun&) = default;
};
// Gives every control point of the region the staff's tension, continuity and bias, and the
// staff's acceleration to the spans the region covers (thesis Accer(is, ie)). A span's
// acceleration is carried by the control point it starts from (SPEC §2.1), so the region's last
// point keeps its own: it starts the span after the region, unless the region is the whole path.
// Values are clamped to [-1, 1]; a region outside the path changes only the points inside it.
// Returns the region's values as they were (staff_runs before the change).
std::vector<StaffRun> apply_staff_to_region(ControlPoints& points, ControlRegion region, const StaffValues& staff);

std::vector<StaffRun> staff_runs(const ControlPoints& points, ControlRegion region);
// Gives the region's control points back the values `runs` holds (staff_runs of the same region).
void restore_staff_runs(ControlPoints& points, ControlRegion region, const std::vector<StaffRun>& runs);
// Whether some run has a tension, continuity or bias other than `shape`'s (each clamped to
// [-1, 1]): the path's segments change when the region goes from one to the other; an acceleration
// alone moves only the in-betweens.
bool runs_change_shape(const std::vector<StaffRun>& runs, const StaffValues& shape);

} // namespace apcs
