#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/control_point.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/geometry/affine.h"
#include "apcs/geometry/vec3.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace apcs {

// Frames FROM … TO of a behaviour or of a KEYS animation (0 ≤ from ≤ to ≤ the scene's last frame).
struct FrameSpan {
    int from = 0;
    int to = 0;

    // Frames of the behaviour by frame f: 0 before FROM, held after TO.
    constexpr int elapsed(int f) const { return (f < from ? from : f > to ? to : f) - from; }

    friend constexpr bool operator==(const FrameSpan&, const FrameSpan&) = default;
};

// MOVE (SPEC §8.1): along a KB path, by P(s(f)) − P_0.
struct SceneMove {
    ControlPoints path; // three-column files take the object's staff values
    // TIMES: the frame at which each control point is reached; empty: spread over `frames`.
    std::vector<int> times;
    FrameSpan frames; // TIMES' first and last, or FROM/TO
    bool loop = false;
    // ALIGN: the object turns with the path's direction (the tangent, or with AHEAD D the chord to
    // the first later point of the path D away: a two-axle vehicle's axles D apart).
    bool align = false;
    std::optional<double> ahead;

    friend bool operator==(const SceneMove&, const SceneMove&) = default;
};

// ROTATE: degrees_per_frame × (f − from) about +axis through `about` (default: the object's centre).
struct SceneRotate {
    double degrees_per_frame = 0.0;
    Axis axis = Axis::x;
    std::optional<Vec3> about;
    FrameSpan frames;
};

// ROLL (SPEC §8.1): a wheel whose turn in the world (its parents' turns included) is, at every
// frame, the distance its hub (`about`, default the object's centre) has travelled / radius, rolling
// it forward: a negative turn about +axis going +y for AXIS x. A negative radius rolls the other way.
struct SceneRoll {
    double radius = 1.0; // ≠ 0
    Axis axis = Axis::x;
    std::optional<Vec3> about;
    int line = 0; // the ROLL line
};

// SCALE: factor^(f − from) per axis of the scene about `about` (default: the object's centre);
// one FACTOR scales all three axes (Net_Anim's ExtendX/ExtendY are the y and z factors).
struct SceneScale {
    Vec3 factors{1.0, 1.0, 1.0};
    std::optional<Vec3> about;
    FrameSpan frames;
};

// JOINT: a key point (thesis Ch. 3.3): point `point` (0-based) of the object's drawing, or the
// centroid of points `point` … `last_point` (the thesis' joints are contact regions).
struct SceneJoint {
    std::string name;
    std::size_t point = 0;
    std::size_t last_point = 0; // = point for a joint of one point
    std::optional<double> tolerance; // unset: 0.001 × the diagonal of all frame-0 drawings
    int line = 0;
};

// The joint's place among an object's points: the centroid of points first … last.
inline Vec3 joint_place(std::span<const Vec3> points, std::size_t first, std::size_t last)
{
    Vec3 sum{};
    for (std::size_t p = first; p <= last; ++p)
        sum += points[p];
    return sum * (1.0 / static_cast<double>(last - first + 1));
}

// KEYS: KEY1 up to frame `frames.from`, the in-betweens fitted along the paths of the first and
// last graphic point, KEY2 from frame `frames.to`.
struct SceneKeys {
    EqualisedKeys keys;
    ControlPoints first_path;
    ControlPoints last_path;
    // Each PATHS file's SLOPES line, the end slopes it was adjusted with (SPEC §2.1); unset: the
    // command's --slopes. apcs play --slopes overrides them, as apcs fit's does.
    std::optional<EndSlopes> first_slopes;
    std::optional<EndSlopes> last_slopes;
    FrameSpan frames;
};

// A part's anchor (SPEC §8.2): the first of its joints, in its JOINT lines' order, whose other end
// is a part declared before it (its partner). Indices into the parts' `joints` and Scene::objects.
struct SceneAnchor {
    std::size_t joint = 0;
    std::size_t partner = 0;
    std::size_t partner_joint = 0;
};

// One OBJECT line and what follows it: a part when it has a parent.
struct SceneObject {
    std::string name;
    int line = 0; // the OBJECT line
    std::optional<std::size_t> parent; // index of an object declared before
    std::optional<Graphic> shape;
    std::optional<SceneKeys> keys;
    StaffValues staff;       // its own STAFF, or its parent's, or the command line's
    bool own_staff = false;  // STAFF given on this object
    std::optional<SceneMove> move;
    std::optional<SceneRotate> rotate;
    std::optional<SceneRoll> roll; // not with a ROTATE: one turn of its own
    std::optional<SceneScale> scale;
    std::vector<SceneJoint> joints;
    std::optional<SceneAnchor> anchor; // set when the scene has been read whole
    // RIGID (the line it is on; 0: not rigid): its key frames are in-betweened as a turn about its
    // anchor, so it keeps its shape (SPEC §8.2).
    int rigid_line = 0;

    bool rigid() const { return rigid_line != 0; }
    // Whether its T_f needs Net_Anim's ticks (SPEC §8.2): it turns or scales. One that only moves
    // is translated by its MOVE's offset.
    bool accumulates() const { return rotate || roll || scale || (move && move->align); }
    bool has_drawing() const { return shape.has_value() || keys.has_value(); }
    // Its drawing at frame 0 (SHAPE, or KEY1 after adding points); a group has none.
    const Graphic* first_drawing() const { return shape ? &*shape : keys ? &keys->keys.key1 : nullptr; }
};

// A .scn file read and checked (SPEC §8): frames 0 … last_frame, objects in file order, every
// parent before its children.
struct Scene {
    int last_frame = 0;
    std::optional<ViewAngles> view; // VIEW THETA PHI
    // SPACING nearest|exact (SPEC §8.1): where the in-betweens of its MOVE and KEYS paths fall;
    // unset, exact (a MOVE at even steps). --spacing overrides it (scene_path_settings).
    std::optional<Spacing> spacing;
    std::vector<SceneObject> objects;
};

} // namespace apcs
