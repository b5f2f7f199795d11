#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/surface_construction.h"
#include "apcs/geometry/affine.h"
#include "apcs/scene/actor_state.h"
#include "apcs/scene/rigid_turn.h"
#include "apcs/scene/scene.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace apcs {

// Where an object's points sit in a frame of the whole scene (a group has none).
struct ObjectPoints {
    std::size_t first = 0;
    std::size_t count = 0;
};

// An object whose world points leave what a .dat file holds (|value| <= max_dat_magnitude, and
// finite) at `frame`: its transforms composed with its parents' (ten nested SCALE 1.148 over 100
// frames reach 1e57), its drawing moved far enough (SHAPE at 1e9 with MOVE 1e9), or, for a part
// with an anchor (`at_anchor`), its points put on its partner's point (a RIGID part turned about
// it). `magnitude` is the largest |value| (NaN when one is not a number).
struct OutOfReach {
    std::size_t object = 0;
    int frame = 0;
    double magnitude = 0;
    bool at_anchor = false;
};

// The path settings a scene plays with (SPEC §8.1): the command's (`command`), but the spacing is
// the scene's SPACING line's unless the command line gave --spacing (`spacing_given`), which
// overrides the file. Without either it is exact (SPEC §8.1, turn 5): nearest made a MOVE stand
// still every 9th frame of 36 on a 32-sample road; a scene that must equal a session's in-between
// files says SPACING nearest.
PathSettings scene_path_settings(const Scene& scene, const PathSettings& command, bool spacing_given);

// A scene's frames, one at a time (SPEC §8.2): each object's transform W_f = W_f(parent) ∘ T_f,
// T_f Net_Anim's accumulation of its MOVE, ALIGN, ROTATE, ROLL and SCALE one tick a frame
// (tick, actor_state.h), applied to its frame-f drawing (SHAPE, or the KEYS frame); then a part whose anchor is more than its
// tolerance apart is moved by the separation, and the parts anchored through it with it (a part
// without an anchor moves with its parent). A RIGID part is its KEY1 drawing turned, by its law, a
// fraction of the way to KEY2, its anchor on its partner's point. What every frame needs
// (the KEYS frames, the MOVE offsets, the states of
// the objects that turn or scale: one affine map a frame each) is computed once, here; `scene` must outlive this.
class SceneAnimation {
public:
    // `settings` give the KB sampling, the end slopes and the spacing of MOVE and KEYS paths;
    // their in-between counts come from the frames of each behaviour. KEYS objects are fitted by
    // `construction` (SPEC §5.3, §5.3.1).
    SceneAnimation(const Scene& scene, const PathSettings& settings,
                   SurfaceConstruction construction = SurfaceConstruction::blend);

    int last_frame() const { return m_scene.last_frame; }
    std::size_t frame_count() const { return static_cast<std::size_t>(m_scene.last_frame) + 1; }
    std::size_t points_per_frame() const { return m_points_per_frame; }
    // Every object's world points at frame f, laid out as object_points() says.
    void frame(int f, std::span<Vec3> points) const;
    std::vector<Vec3> frame(int f) const;
    // The transform W_f of object `index`, without joint corrections.
    Affine transform(std::size_t index, int f) const;
    // The first frame, and in it the first object in file order, whose drawing W_f moves past
    // `limit` (or to values that are not numbers); nullopt when every frame can be written and
    // read back. A part with an anchor is judged by its points, after it is put on its partner's
    // point (and a RIGID one turned): the whole frame is computed for those.
    std::optional<OutOfReach> first_out_of_reach(double limit) const;
    std::span<const ObjectPoints> object_points() const { return m_object_points; }
    // The parts of all objects' drawings in file order, each named "OBJECT/PART" ("OBJECT/P1" … for
    // parts without a name): the structure that draws a frame.
    const Graphic& structure() const { return m_structure; }
    // All frames 0 … N, for the player and the pictures.
    FrameSequence all_frames() const;
    // The centre an object's ROTATE and SCALE default to: the middle of its frame-0 drawing's box,
    // or of its descendants' drawings for a group.
    const Vec3& centre(std::size_t index) const { return m_centres[index]; }

private:
    // A part's anchor (SPEC §8.2): points point … last of its drawing meet points partner_point …
    // partner_last of its partner's.
    struct AnchorLink {
        std::size_t point;
        std::size_t last;
        std::size_t partner;
        std::size_t partner_point;
        std::size_t partner_last;
        double tolerance;
    };
    // A RIGID part: its KEY1 drawing, the whole turn to KEY2, the law and the frames it turns over.
    struct RigidMotion {
        RigidTurn turn;
        Vec3 anchor; // its anchor's place in the KEY1 drawing, the centre of the turn
        double acceleration;
        FrameSpan frames;
    };
    // Which of the object's MOVE offsets (and ALIGN turns) frame f shows; none before the MOVE.
    std::optional<std::size_t> move_step(std::size_t index, int f) const;
    Vec3 move_offset(std::size_t index, int f) const;
    // T_f of the object alone: its MOVE, ALIGN, ROTATE, ROLL and SCALE, without its parents'.
    Affine own_transform(std::size_t index, int f) const;
    // The states of every object that accumulates, frames 0 … N (scene_accumulation.cpp).
    void accumulate();
    void accumulate_object(std::size_t index);
    // Frame f's tick, from frame f − 1: its ALIGN's and ROTATE's turns, its SCALE's factors.
    std::vector<TickTurn> tick_turns(std::size_t index, int f) const;
    std::optional<TickScale> tick_scale(std::size_t index, int f) const;
    // The ROLL's turn of the tick: the part's turn in the world, parents' included, grows by the
    // hub's travel (in the world, by the tick's other changes and the parents') / radius.
    TickTurn roll_turn(std::size_t index, int f, const ActorState& before, std::span<const TickTurn> turns,
                       const std::optional<TickScale>& scale) const;
    std::span<const Vec3> drawing_at(std::size_t index, int f) const;
    // A RIGID part's points at frame f: KEY1 turned by law(τ) of the whole turn, moved by `world`,
    // its anchor put on its partner's joint point in `points` (the partner's already placed).
    void place_rigid(std::size_t index, int f, const Affine& world, std::span<Vec3> points) const;
    // A part that is not RIGID: its drawing moved by `world` and `shift`, then onto its partner's
    // joint point if farther than the tolerance; the shift it ends with.
    Vec3 place_drawing(std::size_t index, int f, const Affine& world, Vec3 shift, std::span<Vec3> points) const;
    void links(const Scene& scene);
    // The object's KEYS frames and, `with_move`, its MOVE offsets (and ALIGN turns).
    void fit_behaviours(std::size_t index, const PathSettings& settings, SurfaceConstruction construction,
                        bool with_move);

    const Scene& m_scene;
    std::vector<Vec3> m_centres;
    std::vector<FrameSequence> m_key_frames;       // per object: its KEYS frames FROM … TO
    std::vector<std::vector<Vec3>> m_drawings;      // per object: its SHAPE's points (empty for KEYS)
    std::vector<std::vector<Vec3>> m_move_offsets;  // per object: MOVE offset at FROM … TO
    std::vector<std::vector<Affine>> m_move_turns;  // per object with ALIGN: its turn at FROM … TO, until accumulated
    std::vector<std::vector<ActorState>> m_states;  // per object that accumulates: frames 0 … N
    std::vector<std::optional<AnchorLink>> m_anchors;
    std::vector<std::optional<RigidMotion>> m_rigid;
    std::vector<ObjectPoints> m_object_points;
    std::size_t m_points_per_frame = 0;
    Graphic m_structure;
};

// A control point of an object's MOVE … TIMES path, where the object's MOVE has brought the point
// that stood at the first control point by the frame TIMES names (the slides' car at A at frame 0,
// B at 10, …). World units: its parents' transforms at that frame applied; joint corrections not.
struct TimedWaypoint {
    std::size_t object = 0;
    int frame = 0;
    Vec3 position;
};

// Every MOVE … TIMES control point of the scene `animation` plays, by object in file order, then
// by frame; none for a MOVE without TIMES.
std::vector<TimedWaypoint> timed_waypoints(const Scene& scene, const SceneAnimation& animation);

// The MOVE offsets P(s(f)) − P_0 for frames move.frames.from … move.frames.to (SPEC §8.1): by
// TIMES through TimedDistance on the true arc length, else each span's share of the frames in
// proportion to its length and its distances by its acceleration law (evaluate_path).
std::vector<Vec3> move_offsets(const SceneMove& move, const PathSettings& settings);

} // namespace apcs
