#include "roll_turn.h"

#include "apcs/scene/actor_state.h"

#include <cmath>
#include <numbers>

namespace apcs {

RollPlane roll_plane(Axis axis)
{
    switch (axis) {
    case Axis::y:
        return {{0, 0, 1}, {1, 0, 0}};
    case Axis::z:
        return {{1, 0, 0}, {0, 1, 0}};
    case Axis::x:
        break;
    }
    return {{0, 1, 0}, {0, 0, 1}};
}

double rolled_distance(const RollPlane& plane, const Vec3& step)
{
    const double along = dot(step, plane.forward);
    const double length = std::hypot(along, dot(step, plane.up));
    return along < 0.0 ? -length : length;
}

double turn_in_plane(const RollPlane& plane, const Affine& map)
{
    const Vec3 forward = linear_part(map)(plane.forward);
    return std::atan2(dot(forward, plane.up), dot(forward, plane.forward));
}

double roll_step(double distance, double radius, double others)
{
    return -distance / radius - std::remainder(others, 2.0 * std::numbers::pi);
}

} // namespace apcs
