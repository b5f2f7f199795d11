#pragma once

#include "apcs/geometry/affine.h"
#include "apcs/geometry/vec3.h"

namespace apcs {

// The plane a ROLL turns in (SPEC §8.1), in world coordinates: across its AXIS, `forward` the way it
// rolls forward (+y for AXIS x, +z for y, +x for z) and `up` = axis × forward, away from the road
// below it. A wheel about +x moving +y on a road below turns clockwise in the face-on view: by a
// negative angle about +x.
struct RollPlane {
    Vec3 forward;
    Vec3 up;
};

RollPlane roll_plane(Axis axis);

// How far a hub's `step` goes in the plane (its part along the axis does not roll the wheel):
// positive forward, negative backward.
double rolled_distance(const RollPlane& plane, const Vec3& step);

// The turn, in radians by the right-hand rule about the plane's axis, that the linear part of `map`
// gives the forward direction, measured in the plane (−π … π): a part's turn in the world.
double turn_in_plane(const RollPlane& plane, const Affine& map);

// The ROLL's own turn this tick, in radians about its axis: what makes the part's turn in the
// world change by −distance / radius when its parents and its other turns alone would change it by
// `others` radians (any multiple of a whole turn is taken as the nearest, so `others` is
// reduced to −π … π). `radius` ≠ 0; a negative one rolls the other way.
double roll_step(double distance, double radius, double others);

} // namespace apcs
