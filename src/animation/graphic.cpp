#include "apcs/animation/graphic.h"

namespace apcs {

std::size_t Graphic::point_count() const
{
    std::size_t count = 0;
    for (const GraphicPart& part : parts)
        count += part.points.size();
    return count;
}

std::vector<Vec3> Graphic::all_points() const
{
    std::vector<Vec3> points;
    points.reserve(point_count());
    for (const GraphicPart& part : parts)
        points.insert(points.end(), part.points.begin(), part.points.end());
    return points;
}

Graphic Graphic::with_points(const std::vector<Vec3>& points) const
{
    Graphic copy = *this;
    std::size_t next = 0;
    for (GraphicPart& part : copy.parts)
        for (Vec3& point : part.points)
            point = next < points.size() ? points[next++] : point;
    return copy;
}

} // namespace apcs
