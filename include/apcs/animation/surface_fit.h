#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/motion_path.h"

#include <array>
#include <span>
#include <utility>
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

// Surface fitting (thesis s_fiting.c, Ch. 3.2, SPEC §5.3): each interior point's path taken from
// the two edge paths so that the in-betweens change monotonically. A transfinite blend, linear
// along each point's progress and cubic (F1, F2) across the graphic: with v_i the point's place
// along the graphic, E0_k, E1_k the edge positions and w0_k, w1_k their progress in frame k,
//   w_i,k = F1(v_i)·w0_k + F2(v_i)·w1_k
//   D0_k  = E0_k − lerp(K1_first, K2_first, w0_k)      D1_k = E1_k − lerp(K1_last, K2_last, w1_k)
//   P_i,k = lerp(K1_i, K2_i, w_i,k) + F1(v_i)·D0_k + F2(v_i)·D1_k
// When both edges run straight at even steps every point moves along its own straight line at
// even steps. A closed graphic's last point is its first: K_last = K_first, E1 = E0 (the first
// path) and w1 = w0. key1 and key2 hold the same number of points (equalised); the edges hold the
// same number of frames. Frame 0 is KEY1 and frame M+1 KEY2, exactly, and the first and last point
// follow their edge paths exactly. Cost: O(points × frames).
FrameSequence fit_surface(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure,
                          const EdgePath& first_edge, const EdgePath& last_edge);

// fit_surface one run of points at a time: any points of any frame computed on their own, so that
// frames are written as they are made, on several cores, and never held all at once. Holds the
// keys' spans (which must outlive it), F1(v_i) and F2(v_i) per point, and the edges.
class SurfaceFitter {
public:
    SurfaceFitter(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure, EdgePath first_edge,
                  EdgePath last_edge);

    std::size_t frame_count() const { return m_frame_count; }
    std::size_t point_count() const { return m_point_count; }
    std::span<const Vec3> key1() const { return m_key1; }
    std::span<const Vec3> key2() const { return m_key2; }
    // Points first … first + out.size() − 1 of frame k (both within the counts).
    void fit(std::size_t k, std::size_t first, std::span<Vec3> out) const;

private:
    std::span<const Vec3> m_key1;
    std::span<const Vec3> m_key2;
    bool m_closed = false;
    std::size_t m_point_count = 0;
    std::size_t m_frame_count = 0;
    EdgePath m_first_edge;
    EdgePath m_second_edge;
    std::vector<std::pair<double, double>> m_across; // F1(v_i), F2(v_i)
    bool m_last_follows_edge = true;
};

// A graphic's points as one span: its only part's own, or all parts' copied into `storage`.
std::span<const Vec3> contiguous_points(const Graphic& graphic, std::vector<Vec3>& storage);

// The fitter of a key-frame pair (see fit_key_frames); it refers to the keys' points, or to
// `storage` for keys of several parts, and must not outlive them.
SurfaceFitter key_frames_fitter(const EqualisedKeys& keys, const EvaluatedPath& first_path,
                                const EvaluatedPath& last_path, std::array<std::vector<Vec3>, 2>& storage);

// All frames of a key-frame pair: the edges come from the evaluated paths of the first and last
// graphic point (the last is ignored for a closed graphic), the keys must be equalised.
FrameSequence fit_key_frames(const EqualisedKeys& keys, const EvaluatedPath& first_path, const EvaluatedPath& last_path);

} // namespace apcs
