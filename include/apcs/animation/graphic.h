#pragma once

#include "apcs/geometry/vec3.h"

#include <string>
#include <vector>

namespace apcs {

enum class Closure { open, closed };

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
    // The same parts with the point sequence replaced (sizes must match point_count()).
    Graphic with_points(const std::vector<Vec3>& points) const;
};

} // namespace apcs
