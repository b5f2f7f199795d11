#include "apcs/animation/graphic.h"

namespace apcs {

std::size_t Graphic::point_count() const { return total_point_count(parts); }

std::vector<Vec3> Graphic::all_points() const
{
    std::vector<Vec3> points;
    points.reserve(point_count());
    for (const GraphicPart& part : parts)
        points.insert(points.end(), part.points.begin(), part.points.end());
    return points;
}

std::vector<std::vector<Vec3>> Graphic::polylines(std::span<const Vec3> points) const
{
    std::vector<std::vector<Vec3>> drawn;
    drawn.reserve(parts.size());
    std::size_t next = 0;
    for (const GraphicPart& part : parts) {
        std::vector<Vec3> polyline;
        polyline.reserve(part.points.size() + 1);
        for (std::size_t i = 0; i < part.points.size() && next < points.size(); ++i)
            polyline.push_back(points[next++]);
        if (part.closure == Closure::closed && !polyline.empty() && !(polyline.front() == polyline.back()))
            polyline.push_back(polyline.front());
        drawn.push_back(std::move(polyline));
    }
    return drawn;
}

} // namespace apcs
