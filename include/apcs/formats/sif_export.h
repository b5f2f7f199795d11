#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/view_transform.h"
#include "apcs/geometry/vec3.h"

#include <span>
#include <string>
#include <vector>

namespace apcs {

// A point of the view plane: x_e, y_e of SPEC §4.5 before the perspective division, in world units.
struct PlanePoint {
    double x = 0.0;
    double y = 0.0;
};

// The parallel projection along the view (SPEC §7.5): no SCF, no centring, so `top` maps (x, y, 0)
// to (x, y), `front` (0, u, v) to (u, v) and `side` (u, 0, v) to (u, v).
class ParallelView {
public:
    explicit ParallelView(ViewAngles angles);
    PlanePoint operator()(const Vec3& world) const;

private:
    double m_sin_theta;
    double m_cos_theta;
    double m_sin_phi;
    double m_cos_phi;
};

// How the moving circle of a path's document moves: through TCB waypoints at the control points
// (Synfig's spline, the same as APCS's but for end slopes and acceleration), or through linear
// waypoints at APCS's own frames (KEY1, the in-betweens, KEY2: everything kept, chords between).
enum class SifMotion { tcb, frames };

struct SifTiming {
    int frames_per_span = 12; // tcb: Synfig frames from one control point's waypoint to the next
    double fps = 24.0;
};

struct SifPathRequest {
    std::span<const ControlPoint> points;
    EndSlopes slopes;
    ViewAngles view;
    SifTiming timing;
    SifMotion motion = SifMotion::tcb;
    // SifMotion::frames: the positions of every frame, KEY1 first and KEY2 last.
    std::span<const Vec3> frames;
    std::string name; // the document's name: the path file's
};

// What a TCB document cannot carry of `points` and `slopes`, one sentence each (empty when all of
// it is carried): end slopes other than 1 1, and the accelerations that are not 0.
std::vector<std::string> sif_left_out(std::span<const ControlPoint> points, EndSlopes slopes);

// The Synfig document (canvas version 1.2) of one point's path: the curve as an outline (exactly,
// as Hermite tangents), the control points marked (up to most_marked_control_points), and a red
// circle on top whose `origin` moves along the path as `request.motion` says.
inline constexpr std::size_t most_marked_control_points = 1000;
std::string sif_path_document(const SifPathRequest& request);

struct SifAnimationRequest {
    const Graphic& structure; // the parts (KEY1's, after adding points) the frames' points make
    const FrameSequence& frames;
    ViewAngles view;
    double fps = 24.0;
    std::string name;
};

// The Synfig document of a whole animation: each part an outline whose vertices move through the
// frames, one linear waypoint a frame (frame k at Synfig frame k), so Synfig plays APCS's frames.
std::string sif_animation_document(const SifAnimationRequest& request);

} // namespace apcs
