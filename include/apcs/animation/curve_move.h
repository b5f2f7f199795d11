#pragma once

#include "apcs/animation/hermite.h"
#include "apcs/geometry/vec3.h"

#include <span>

namespace apcs {

// A point of a curve after a change, and the nearest point of the curve before it (world units).
struct SampleMove {
    Vec3 before;
    Vec3 after;
    double distance = 0.0; // |after − before|
};

// How far a change moved a segment (SPEC §7.2.1, "said in numbers"): of its samples after the
// change (j = 0 … basis.size() − 1, as SampledCurve places them; `basis` is its
// hermite_basis_table), the one furthest from the polyline of its samples before, with the nearest
// point of that polyline. Only the polyline's pieces within `window` samples of j are searched, so
// the distance may exceed the true nearest one (an upper bound: "moved up to"), never fall short
// of it; a point that slides along the curve is not counted as a move, as the eye does not see it.
// `at_least`: a segment whose samples all moved by no more than that (sample to same sample, a
// bound of the nearest distance) is not searched: {distance 0}.
SampleMove furthest_sample_move(const HermiteSegment& before, const HermiteSegment& after,
                                std::span<const HermiteBasis> basis, double at_least = 0.0, int window = 4);

} // namespace apcs
