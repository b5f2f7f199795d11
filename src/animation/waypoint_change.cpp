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

namespace {

// What inserting, removing or moving the point at `index` does to the points.
PathChange inserted_at(std::size_t index) { return {index, 0, 1, PathChange::What::positions}; }
PathChange removed_at(std::size_t index) { return {index, 1, 0, PathChange::What::positions}; }
PathChange moved_at(std::size_t index) { return {index, 1, 1, PathChange::What::positions}; }

} // namespace

PathChange apply_change(ControlPoints& points, std::vector<std::size_t>& origins, const WaypointChange& change)
{
    switch (change.kind) {
    case Kind::insert: insert_point(points, origins, change.index, change.point, new_point); return inserted_at(change.index);
    case Kind::remove: remove_point(points, origins, change.index); return removed_at(change.index);
    case Kind::move: move_point(points, change.index, change.offset); return moved_at(change.index);
    }
    return moved_at(change.index);
}

PathChange revert_change(ControlPoints& points, std::vector<std::size_t>& origins, const WaypointChange& change)
{
    switch (change.kind) {
    case Kind::insert: remove_point(points, origins, change.index); return removed_at(change.index);
    case Kind::remove:
        insert_point(points, origins, change.index, change.point, change.origin);
        return inserted_at(change.index);
    case Kind::move: move_point(points, change.index, -1.0 * change.offset); return moved_at(change.index);
    }
    return moved_at(change.index);
}

void apply_change(ControlPoints& points, const WaypointChange& change)
{
    std::vector<std::size_t> origins(points.size());
    apply_change(points, origins, change);
}

void revert_change(ControlPoints& points, const WaypointChange& change)
{
    std::vector<std::size_t> origins(points.size());
    revert_change(points, origins, change);
}

} // namespace apcs
