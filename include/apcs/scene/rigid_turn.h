#pragma once

#include "apcs/geometry/affine.h"
#include "apcs/geometry/vec3.h"

#include <array>
#include <cstddef>
#include <span>

namespace apcs {

// How a RIGID part's KEY2 drawing is its KEY1 drawing turned and moved (SPEC §8.2): the turn that
// best carries KEY1's points, about their centroid, onto KEY2's (least squares, Kabsch's method),
// and how far the worst point is off after it.
struct RigidTurn {
    // The whole turn as a unit quaternion (w, x, y, z) with w >= 0: the smallest rotation between
    // the two poses. A drawing on one line turns by the smallest rotation between its directions,
    // not about its own line.
    std::array<double, 4> quaternion{1.0, 0.0, 0.0, 0.0};
    std::size_t worst_point = 0; // 0-based
    double worst_deviation = 0.0;
    double size = 0.0; // the diagonal of KEY1's bounding box
};

// How far a RIGID part's KEY2 may be from its KEY1 turned and moved: this fraction of its size.
inline constexpr double rigid_congruence = 1e-4;

// `key1` and `key2` have the same number of points, at least one.
RigidTurn fit_rigid_turn(std::span<const Vec3> key1, std::span<const Vec3> key2);

// The fraction `fraction` of the turn (slerp from no turn; 1 is the whole turn) about `centre`.
Affine partial_turn(const RigidTurn& turn, double fraction, const Vec3& centre);

} // namespace apcs
