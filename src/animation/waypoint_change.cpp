#include "apcs/animation/waypoint_change.h"

#include <cassert>
#include <numeric>

namespace apcs {

namespace {

using Kind = WaypointChange::Kind;

void insert_point(ControlPoints& points, std::vector<std::size_t>& origins, std::size_t index,
                  const ControlPoint& point, std::size_t origin)
{
    assert(index <= points.size() && points.size() == origins.size());
    points.insert(points.begin() + static_cast<std::ptrdiff_t>(index), point);
    origins.insert(origins.begin() + static_cast<std::ptrdiff_t>(index), origin);
}

void remove_point(ControlPoints& points, std::vector<std::size_t>& origins, std::size_t index)
{
    assert(index < points.size() && points.size() == origins.size());
    points.erase(points.begin() + static_cast<std::ptrdiff_t>(index));
    origins.erase(origins.begin() + static_cast<std::ptrdiff_t>(index));
}

void move_point(ControlPoints& points, std::size_t index, const Vec3& offset)
{
    assert(index < points.size());
    points[index].position = points[index].position + offset;
}

} // namespace

std::vector<std::size_t> file_origins(std::size_t point_count)
{
    std::vector<std::size_t> origins(point_count);
    std::iota(origins.begin(), origins.end(), std::size_t{0});
    return origins;
}

std::size_t wrapped_point(std::size_t index, int by, std::size_t count)
{
    assert(count > 0);
    const auto n = static_cast<long long>(count);
    return static_cast<std::size_t>(((static_cast<long long>(index) + by) % n + n) % n);
}

void apply_change(ControlPoints& points, std::vector<std::size_t>& origins, const WaypointChange& change)
{
    switch (change.kind) {
    case Kind::insert: return insert_point(points, origins, change.index, change.point, new_point);
    case Kind::remove: return remove_point(points, origins, change.index);
    case Kind::move: return move_point(points, change.index, change.offset);
    }
}

void revert_change(ControlPoints& points, std::vector<std::size_t>& origins, const WaypointChange& change)
{
    switch (change.kind) {
    case Kind::insert: return remove_point(points, origins, change.index);
    case Kind::remove: return insert_point(points, origins, change.index, change.point, change.origin);
    case Kind::move: return move_point(points, change.index, -1.0 * change.offset);
    }
}

} // namespace apcs
