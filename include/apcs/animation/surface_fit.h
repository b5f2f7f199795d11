#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/motion_path.h"

#include <span>
#include <vector>

namespace apcs {

// One edge of the surface: a graphic point's positions in frames 0 … M+1 (KEY1, the M shown
// in-betweens, KEY2) and the fraction of its path reached in each (0 … 1).
struct EdgePath {
    std::vector<Vec3> positions;
    std::vector<double> progress;
};

// Frame 0 = the KEY1 position, frames 1 … M = the path's in-betweens, frame M+1 = the KEY2 position.
EdgePath edge_path_from(const EvaluatedPath& path, const Vec3& key1_position, const Vec3& key2_position);

// Each point's place v_i ∈ [0, 1] along the graphic: the normalised cumulative chord length of the
// point sequence, averaged over both keys. A closed graphic includes its closing segment, so v
// wraps (the last point is short of 1 unless it repeats the first). A key of zero length uses the
// point's index instead.
std::vector<double> graphic_parameters(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure);

// Surface fitting (thesis s_fiting.c, SPEC §5.3), the bicubically blended Coons form of the
// Ferguson surface with u along the paths and v along the graphic:
//   P_i,k = F1(v_i)·E0_k + F2(v_i)·E1_k + F1(w_k)·(K1_i − F1(v_i)·K1_first − F2(v_i)·K1_last)
//                                      + F2(w_k)·(K2_i − F1(v_i)·K2_first − F2(v_i)·K2_last)
// with E0, E1 the first and last point's edge paths and w_k their mean progress. A closed
// graphic uses the first edge for both (E1 = E0). key1 and key2 hold the same number of points
// (equalised); the edges hold the same number of frames. Frame 0 is KEY1 and frame M+1 KEY2,
// exactly. Cost: O(points × frames).
FrameSequence fit_surface(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure,
                          const EdgePath& first_edge, const EdgePath& last_edge);

// All frames of a key-frame pair: the edges come from the evaluated paths of the first and last
// graphic point (the last is ignored for a closed graphic), the keys must be equalised.
FrameSequence fit_key_frames(const EqualisedKeys& keys, const EvaluatedPath& first_path, const EvaluatedPath& last_path);

} // namespace apcs
