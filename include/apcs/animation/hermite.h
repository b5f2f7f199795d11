#pragma once

#include "apcs/base/large_array.h"
#include "apcs/geometry/vec3.h"

namespace apcs {

// The Hermite blending functions of thesis Ch. 2.1 (F1..F4), u in [0, 1].
struct HermiteBasis {
    double f1 = 0.0; // weight of P(0)
    double f2 = 0.0; // weight of P(1)
    double f3 = 0.0; // weight of P'(0)
    double f4 = 0.0; // weight of P'(1)
};

constexpr HermiteBasis hermite_basis(double u)
{
    const double u2 = u * u;
    const double u3 = u2 * u;
    return {2.0 * u3 - 3.0 * u2 + 1.0, -2.0 * u3 + 3.0 * u2, u3 - 2.0 * u2 + u, u3 - u2};
}

// Derivatives of F1..F4 with respect to u, for arc length (speed = |P'(u)|).
constexpr HermiteBasis hermite_basis_derivative(double u)
{
    const double u2 = u * u;
    return {6.0 * u2 - 6.0 * u, -6.0 * u2 + 6.0 * u, 3.0 * u2 - 4.0 * u + 1.0, 3.0 * u2 - 2.0 * u};
}

// P(u) = P0·F1 + P1·F2 + T0·F3 + T1·F4.
struct HermiteSegment {
    Vec3 start;
    Vec3 end;
    Vec3 start_tangent;
    Vec3 end_tangent;

    constexpr Vec3 apply(const HermiteBasis& basis) const
    {
        return start * basis.f1 + end * basis.f2 + start_tangent * basis.f3 + end_tangent * basis.f4;
    }
    constexpr Vec3 point_at(double u) const { return apply(hermite_basis(u)); }
    constexpr Vec3 derivative_at(double u) const { return apply(hermite_basis_derivative(u)); }
    constexpr bool operator==(const HermiteSegment&) const = default;
};

// A path's segments: 96 MB for 10^6 control points, in 2 MB pages where the kernel gives them
// (opening such a path faulted in 24,000 4 KB pages on one core: PERFORMANCE.md 19).
using HermiteSegments = LargeArray<HermiteSegment>;

} // namespace apcs
