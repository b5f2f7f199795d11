#pragma once

#include "apcs/geometry/vec3.h"

#include <span>
#include <string>
#include <vector>

namespace apcs {

enum class Closure { open, closed };

// The points of all parts together (a graphic's, or a .dat file's whose parts hold `points`).
template <typename Part>
std::size_t total_point_count(const std::vector<Part>& parts)
{
    std::size_t count = 0;
    for (const Part& part : parts)
        count += part.points.size();
    return count;
}

// A polyline of a key frame; drawing lifts the pen between parts. A closed part is drawn back to
// its first point.
struct GraphicPart {
    std::string name;
    Closure closure = Closure::open;
    std::vector<Vec3> points;
};

// One key frame of one object (thesis Ch. 3.2): an ordered list of parts. For surface fitting its
// points, all parts in order, form one sequence.
struct Graphic {
    std::vector<GraphicPart> parts;

    std::size_t point_count() const;
    std::vector<Vec3> all_points() const;
    // A closed graphic is a single closed part (thesis "closed curve"); it needs one path only.
    bool is_closed() const { return parts.size() == 1 && parts[0].closure == Closure::closed; }
    // The first point of the first part and the last of the last: the graphic points whose paths
    // the animator shapes. The graphic must have a point.
    const Vec3& first_point() const { return parts.front().points.front(); }
    const Vec3& last_point() const { return parts.back().points.back(); }
    // The polylines that draw `points` (a sequence laid out like this graphic's points, e.g. one
    // frame) part by part; a closed part ends back at its first point.
    std::vector<std::vector<Vec3>> polylines(std::span<const Vec3> points) const;
};

} // namespace apcs
