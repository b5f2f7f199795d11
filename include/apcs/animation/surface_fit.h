#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/arc_length.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/hermite.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/surface_construction.h"

#include <array>
#include <memory>
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

// An edge path's end tangents as evaluated (§4.2): the outgoing tangent at its first control point
// (S0·(P_1 − P_0), the prompt's DS[0]) and the incoming one at its last (S1·(P_n − P_{n−1})).
struct EdgeTangents {
    Vec3 start;
    Vec3 end;
};
EdgeTangents edge_tangents_of(const EvaluatedPath& path);

// The corners of the thesis' Ferguson surface (Ch. 3.2, fig. 3.2.1): the u-tangents of the first
// and the last point's path at KEY1 (start) and at KEY2 (end).
struct FergusonCorners {
    EdgeTangents first;
    EdgeTangents last;
};

// Point i's path on the Ferguson surface (SPEC §5.3.1): with zero twist the u-tangent along KEY1
// at v is Pu1(v) = F1(v)·T_first,start + F2(v)·T_last,start, along KEY2 Pu2(v) likewise with the
// end tangents; the path is the Hermite segment from K1_i to K2_i with tangents Pu1(v1_i) and
// Pu2(v2_i), v1_i and v2_i the point's chord places along KEY1 and KEY2 (thesis: "the boundary
// through A and B of the sub-surface on 1, 2, A, B"). A closed graphic's last path is its first.
std::vector<HermiteSegment> ferguson_point_paths(std::span<const Vec3> key1, std::span<const Vec3> key2,
                                                 Closure closure, const FergusonCorners& corners);

// One Hermite segment measured once (§4.4), so that the points at many arc fractions cost a
// few steps each, not a measuring: a Ferguson path is asked for every in-between of every point.
// The arc length at sixteen knots (u = j/16), each piece by five-point Gauss-Legendre on its two
// halves, so the length to any u is a knot's plus the same rule once more. The rule on whole
// pieces against it estimates its error (about 1/1000 of their difference); a segment where that
// passes 1e-11 of its length (a near-cusp) is measured as §4.4 measures curves instead
// (CurveArcLengths, adaptive Simpson to 1e-10 of the length), as every segment once was.
class MeasuredSegment {
public:
    static constexpr int knots = 16;

    // A segment of no length at the origin (a place to measure one into).
    MeasuredSegment() = default;
    explicit MeasuredSegment(const HermiteSegment& segment);
    // The point at `fraction` (clamped to [0, 1]) of the arc length, to 1e-12 of it; a segment of
    // no length gives its start.
    Vec3 at_arc_fraction(double fraction) const;

private:
    double length_at(double u) const;

    HermiteSegment m_segment;
    std::array<double, knots + 1> m_at_knot{}; // arc length from u = 0 to u = j / knots
    std::shared_ptr<const CurveArcLengths> m_adaptive; // only for a segment the rule cannot follow
};

// MeasuredSegment(segment).at_arc_fraction(fraction), for one point.
Vec3 point_at_arc_fraction(const HermiteSegment& segment, double fraction);

// Frame 0 = the KEY1 position, frames 1 … M = the path's in-betweens, frame M+1 = the KEY2 position.
EdgePath edge_path_from(const EvaluatedPath& path, const Vec3& key1_position, const Vec3& key2_position);

// Each point's place along one key: the normalised cumulative chord length of its point sequence
// (with the closing segment for a closed graphic); a key of zero length gives i / (n − 1).
std::vector<double> chord_places(std::span<const Vec3> points, Closure closure);

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
    // The thesis' construction (SPEC §5.3.1): interior point i's in-between k lies at the arc
    // fraction F1(v_i)·w0_k + F2(v_i)·w1_k of its Ferguson path (ferguson_point_paths). Cost:
    // O(points × frames) arc-length inversions.
    SurfaceFitter(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure, EdgePath first_edge,
                  EdgePath last_edge, const FergusonCorners& corners);

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
    std::vector<MeasuredSegment> m_ferguson_paths; // empty for the blend
};

// A graphic's points as one span: its only part's own, or all parts' copied into `storage`.
std::span<const Vec3> contiguous_points(const Graphic& graphic, std::vector<Vec3>& storage);

// The fitter of a key-frame pair (see fit_key_frames); it refers to the keys' points, or to
// `storage` for keys of several parts, and must not outlive them.
SurfaceFitter key_frames_fitter(const EqualisedKeys& keys, const EvaluatedPath& first_path,
                                const EvaluatedPath& last_path, std::array<std::vector<Vec3>, 2>& storage,
                                SurfaceConstruction construction = SurfaceConstruction::blend);

// All frames of a key-frame pair: the edges come from the evaluated paths of the first and last
// graphic point (the last is ignored for a closed graphic), the keys must be equalised.
FrameSequence fit_key_frames(const EqualisedKeys& keys, const EvaluatedPath& first_path, const EvaluatedPath& last_path,
                             SurfaceConstruction construction = SurfaceConstruction::blend);

} // namespace apcs
