#pragma once

#include "apcs/animation/motion_path.h"
#include "apcs/geometry/affine.h"
#include "apcs/scene/scene.h"

#include <span>
#include <vector>

namespace apcs {

// The turns of a MOVE with ALIGN (SPEC §8.1), one per entry of `offsets` (offsets[k] = P(s_k) −
// P_0, the rider's place at frame FROM + k): the smallest rotation about P_0 taking the path's
// direction at P_0 to its direction at P(s_k). The direction is the path's tangent, or with AHEAD D
// the chord from P(s_k) to the first later point of the path D away (a two-axle vehicle, its rear
// axle riding the path, its front axle D ahead on it). Where the direction has no length (the end
// of the path nearer than D) the last one is kept. The path is read as a polyline of at least 256
// samples a segment, so a direction is off the curve's by less than its sagitta; each frame's
// place on it is found among all its segments (a cost of frames x samples).
std::vector<Affine> align_turns(const SceneMove& move, std::span<const Vec3> offsets, const PathSettings& settings);

// The smallest rotation (about the origin) taking the direction of `from` to that of `to`; both
// of some length. Opposite directions turn half a turn about an axis across `from`.
Affine smallest_rotation(const Vec3& from, const Vec3& to);

} // namespace apcs
