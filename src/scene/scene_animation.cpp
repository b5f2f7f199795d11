#include "apcs/scene/scene_animation.h"

#include "apcs/animation/arc_length.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/speed_law.h"
#include "apcs/base/parallel_work.h"
#include "apcs/animation/surface_fit.h"
#include "move_align.h"
#include "apcs/geometry/bounding_box.h"
#include "apcs/scene/scene_file.h"
#include "scene_numbers.h"
#include "apcs/scene/timed_distance.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace apcs {

namespace {

PathSettings spread_over(const PathSettings& settings, const FrameSpan& frames)
{
    PathSettings spread = settings;
    spread.inbetween_count = std::max(0, frames.to - frames.from - 1);
    return spread;
}

std::vector<Vec3> timed_offsets(const SceneMove& move, const PathSettings& settings)
{
    const ArcLengthTable table(kb_segments(move.path, settings.slopes));
    std::vector<double> distances(move.path.size());
    for (std::size_t k = 0; k < move.path.size(); ++k)
        distances[k] = table.length_to_segment_start(k);
    const TimedDistance distance(move.times, distances);
    const Vec3 start = move.path.front().position;
    std::vector<Vec3> offsets;
    offsets.reserve(static_cast<std::size_t>(move.frames.to - move.frames.from) + 1);
    std::size_t next_key = 0;
    for (int f = move.frames.from; f <= move.frames.to; ++f) {
        // At its frame a control point is reached exactly, not to the arc length's precision.
        if (f == move.times[next_key]) {
            offsets.push_back(move.path[next_key++].position - start);
            continue;
        }
        offsets.push_back(table.point_at(table.parameter_at(distance.at(f))) - start);
    }
    return offsets;
}

// For each object with a MOVE, the first object before it with the same MOVE (path, frames,
// clauses): a crowd along one path needs its offsets once.
std::vector<std::optional<std::size_t>> first_same_moves(const Scene& scene)
{
    std::vector<std::optional<std::size_t>> same(scene.objects.size());
    std::vector<std::size_t> distinct;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const std::optional<SceneMove>& move = scene.objects[i].move;
        if (!move)
            continue;
        const auto found = std::find_if(distinct.begin(), distinct.end(),
                                        [&](std::size_t j) { return *scene.objects[j].move == *move; });
        if (found != distinct.end())
            same[i] = *found;
        else
            distinct.push_back(i);
    }
    return same;
}

} // namespace

std::vector<Vec3> move_offsets(const SceneMove& move, const PathSettings& settings)
{
    if (!move.times.empty())
        return timed_offsets(move, settings);
    const Vec3 start = move.path.front().position;
    const Vec3 end = move.path.back().position;
    if (move.frames.to == move.frames.from)
        return {end - start};
    const EvaluatedPath path = evaluate_path(move.path, spread_over(settings, move.frames));
    std::vector<Vec3> offsets{Vec3{}};
    offsets.reserve(path.inbetweens.size() + 2);
    for (const Inbetween& inbetween : path.inbetweens)
        offsets.push_back(inbetween.position - start);
    offsets.push_back(end - start);
    return offsets;
}

PathSettings scene_path_settings(const Scene& scene, const PathSettings& command, bool spacing_given)
{
    PathSettings settings = command;
    if (!spacing_given)
        settings.spacing = scene.spacing.value_or(Spacing::exact);
    return settings;
}

SceneAnimation::SceneAnimation(const Scene& scene, const PathSettings& settings, SurfaceConstruction construction)
    : m_scene(scene)
    , m_centres(scene.objects.size())
    , m_key_frames(scene.objects.size())
    , m_drawings(scene.objects.size())
    , m_move_offsets(scene.objects.size())
    , m_move_turns(scene.objects.size())
    , m_states(scene.objects.size())
    , m_anchors(scene.objects.size())
    , m_rigid(scene.objects.size())
    , m_object_points(scene.objects.size())
{
    std::vector<BoundingBox> boxes(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (const Graphic* drawing = object.first_drawing()) {
            std::vector<Vec3> points = drawing->all_points();
            for (std::optional<std::size_t> owner = i; owner; owner = scene.objects[*owner].parent)
                boxes[*owner].add(points);
            m_object_points[i] = {m_points_per_frame, points.size()};
            m_points_per_frame += points.size();
            // A KEYS object draws its fitted frames instead; a RIGID one turns its KEY1 drawing.
            if (object.shape || object.rigid())
                m_drawings[i] = std::move(points);
            for (std::size_t p = 0; p < drawing->parts.size(); ++p) {
                GraphicPart part = drawing->parts[p];
                part.name = object.name + "/" + (part.name.empty() ? "P" + std::to_string(p + 1) : part.name);
                m_structure.parts.push_back(std::move(part));
            }
        }
    }
    // Each object's KEYS frames and MOVE offsets are its own: computed on every core (a scene of
    // 1,000 MOVEs at exact spacing spends its start here), once for objects that share a MOVE.
    const std::vector<std::optional<std::size_t>> same_move = first_same_moves(scene);
    for_each_index_in_parallel(scene.objects.size(), std::max(1u, std::thread::hardware_concurrency()),
                               [&](std::size_t i) { fit_behaviours(i, settings, construction, !same_move[i]); });
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (same_move[i]) {
            m_move_offsets[i] = m_move_offsets[*same_move[i]];
            m_move_turns[i] = m_move_turns[*same_move[i]];
        }
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        m_centres[i] = boxes[i].empty() ? Vec3{} : boxes[i].centre();
    links(scene);
    accumulate();
}

void SceneAnimation::fit_behaviours(std::size_t index, const PathSettings& settings, SurfaceConstruction construction,
                                    bool with_move)
{
    const SceneObject& object = m_scene.objects[index];
    if (object.keys && !object.rigid()) {
        const SceneKeys& keys = *object.keys;
        const PathSettings spread = spread_over(settings, keys.frames);
        const auto with_slopes = [&spread](const std::optional<EndSlopes>& slopes) {
            PathSettings own = spread;
            own.slopes = slopes.value_or(spread.slopes);
            return own;
        };
        m_key_frames[index] = fit_key_frames(keys.keys, evaluate_path(keys.first_path, with_slopes(keys.first_slopes)),
                                             evaluate_path(keys.last_path, with_slopes(keys.last_slopes)), construction);
    }
    if (object.move && with_move) {
        m_move_offsets[index] = move_offsets(*object.move, settings);
        if (object.move->align)
            m_move_turns[index] = align_turns(*object.move, m_move_offsets[index], settings);
    }
}

void SceneAnimation::links(const Scene& scene)
{
    const double default_tolerance = default_joint_tolerance(scene);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (!object.anchor)
            continue;
        const SceneJoint& joint = object.joints[object.anchor->joint];
        const SceneJoint& partner = scene.objects[object.anchor->partner].joints[object.anchor->partner_joint];
        m_anchors[i] = AnchorLink{joint.point, joint.last_point, object.anchor->partner, partner.point, partner.last_point,
                                  joint.tolerance.value_or(partner.tolerance.value_or(default_tolerance))};
        if (!object.rigid())
            continue;
        const EqualisedKeys& keys = object.keys->keys;
        m_rigid[i] = RigidMotion{fit_rigid_turn(keys.key1.all_points(), keys.key2.all_points()),
                                 joint_place(m_drawings[i], joint.point, joint.last_point), object.staff.acceleration,
                                 object.keys->frames};
    }
}

std::optional<std::size_t> SceneAnimation::move_step(std::size_t index, int f) const
{
    const std::optional<SceneMove>& move = m_scene.objects[index].move;
    if (!move || f < move->frames.from)
        return std::nullopt;
    const std::size_t last = m_move_offsets[index].size() - 1;
    const int lap = move->frames.to - move->frames.from;
    if (f >= move->frames.to) {
        if (!move->loop || lap == 0)
            return last;
        // Every lap starts again at P_0: frame FROM + k·lap shows the path's start.
        return static_cast<std::size_t>((f - move->frames.from) % lap);
    }
    return static_cast<std::size_t>(f - move->frames.from);
}

Affine SceneAnimation::transform(std::size_t index, int f) const
{
    const std::optional<std::size_t> parent = m_scene.objects[index].parent;
    return parent ? transform(*parent, f) * own_transform(index, f) : own_transform(index, f);
}

Affine SceneAnimation::own_transform(std::size_t index, int f) const
{
    const Vec3 offset = move_offset(index, f);
    const std::vector<ActorState>& states = m_states[index];
    return states.empty() ? Affine::translation(offset) : actor_transform(states[static_cast<std::size_t>(f)], offset);
}

std::span<const Vec3> SceneAnimation::drawing_at(std::size_t index, int f) const
{
    const std::optional<SceneKeys>& keys = m_scene.objects[index].keys;
    if (!keys)
        return m_drawings[index];
    const int last = keys->frames.to - keys->frames.from;
    return m_key_frames[index].frame(static_cast<std::size_t>(std::clamp(f - keys->frames.from, 0, last)));
}

void SceneAnimation::place_rigid(std::size_t index, int f, const Affine& world, std::span<Vec3> points) const
{
    const RigidMotion& rigid = *m_rigid[index];
    const AnchorLink& anchor = *m_anchors[index];
    const FrameSpan& frames = rigid.frames;
    const double tau = static_cast<double>(frames.elapsed(f)) / (frames.to - frames.from); // KEYS has FROM < TO
    const Affine turned =
        world * partial_turn(rigid.turn, acceleration_distance_fraction(tau, rigid.acceleration), rigid.anchor);
    const ObjectPoints partner = m_object_points[anchor.partner];
    const Vec3 shift = joint_place(points.subspan(partner.first, partner.count), anchor.partner_point, anchor.partner_last) -
                       world(rigid.anchor);
    const ObjectPoints place = m_object_points[index];
    const std::span<Vec3> own = points.subspan(place.first, place.count);
    const std::vector<Vec3>& key1 = m_drawings[index];
    for (std::size_t p = 0; p < own.size(); ++p)
        own[p] = turned(key1[p]) + shift;
}

Vec3 SceneAnimation::place_drawing(std::size_t index, int f, const Affine& world, Vec3 shift, std::span<Vec3> points) const
{
    const ObjectPoints place = m_object_points[index];
    const std::span<Vec3> own = points.subspan(place.first, place.count);
    const std::span<const Vec3> drawing = drawing_at(index, f);
    for (std::size_t p = 0; p < own.size(); ++p)
        own[p] = world(drawing[p]) + shift;
    if (!m_anchors[index])
        return shift;
    // A joint the transforms do not keep moves the part (and, through the shift, the parts
    // anchored through it) onto its partner's key point.
    const AnchorLink& anchor = *m_anchors[index];
    const ObjectPoints partner = m_object_points[anchor.partner];
    const Vec3 target = joint_place(points.subspan(partner.first, partner.count), anchor.partner_point, anchor.partner_last);
    const Vec3 at = joint_place(own, anchor.point, anchor.last);
    const Vec3 separation = target - at;
    // Round-off of the coordinates never decides: a part drawn exactly TOLERANCE from its partner
    // stays where it is drawn (frame 0 as given), as the frame-0 check let it.
    if (at_most_within_round_off(length(separation), anchor.tolerance,
                                 std::max(largest_coordinate(at), largest_coordinate(target))))
        return shift;
    for (Vec3& point : own)
        point += separation;
    return shift + separation;
}

void SceneAnimation::frame(int f, std::span<Vec3> points) const
{
    // Parents and partners come first in the file: each object's world transform and shift start
    // from theirs, computed once per frame.
    std::vector<Affine> world_of(m_scene.objects.size());
    std::vector<Vec3> shift(m_scene.objects.size());
    for (std::size_t i = 0; i < m_scene.objects.size(); ++i) {
        const SceneObject& object = m_scene.objects[i];
        world_of[i] = object.parent ? world_of[*object.parent] * own_transform(i, f) : own_transform(i, f);
        if (m_rigid[i]) {
            place_rigid(i, f, world_of[i], points);
            continue; // placed on its anchor: nothing to pass on
        }
        const std::optional<std::size_t> leader = m_anchors[i] ? std::optional(m_anchors[i]->partner) : object.parent;
        shift[i] = place_drawing(i, f, world_of[i], leader ? shift[*leader] : Vec3{}, points);
    }
}

std::vector<Vec3> SceneAnimation::frame(int f) const
{
    std::vector<Vec3> points(m_points_per_frame);
    frame(f, points);
    return points;
}

FrameSequence SceneAnimation::all_frames() const
{
    FrameSequence frames(frame_count(), m_points_per_frame);
    for (int f = 0; f <= m_scene.last_frame; ++f)
        frame(f, frames.frame(static_cast<std::size_t>(f)));
    return frames;
}

namespace {

// The largest |coordinate| of the box's points moved by `world`: an affine map's largest is at a
// corner. NaN when one is not a number.
double largest_coordinate(const Affine& world, const BoundingBox& box)
{
    double largest = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 point = world(Vec3{(corner & 1) != 0 ? box.high().x : box.low().x,
                                      (corner & 2) != 0 ? box.high().y : box.low().y,
                                      (corner & 4) != 0 ? box.high().z : box.low().z});
        for (const double value : {point.x, point.y, point.z}) {
            if (std::isnan(value))
                return value;
            largest = std::max(largest, std::abs(value));
        }
    }
    return largest;
}

// The largest |coordinate| of `points`; NaN when one is not a number.
double largest_value(std::span<const Vec3> points)
{
    double largest = 0;
    for (const Vec3& point : points)
        for (const double value : {point.x, point.y, point.z}) {
            if (std::isnan(value))
                return value;
            largest = std::max(largest, std::abs(value));
        }
    return largest;
}

} // namespace

std::optional<OutOfReach> SceneAnimation::first_out_of_reach(double limit) const
{
    // Each drawing's box over all its frames, moved by the object's world transform at each frame:
    // objects x frames x 8 corners, not every point of every frame.
    std::vector<BoundingBox> boxes(m_scene.objects.size());
    for (std::size_t i = 0; i < m_scene.objects.size(); ++i) {
        boxes[i].add(m_drawings[i]);
        for (std::size_t k = 0; k < m_key_frames[i].frame_count(); ++k)
            boxes[i].add(m_key_frames[i].frame(k));
    }
    // A part with an anchor is put on its partner's point, and a RIGID one turned about it: where
    // the transforms do not say, so its points are computed.
    const bool anchored = std::any_of(m_anchors.begin(), m_anchors.end(), [](const auto& link) { return link.has_value(); });
    std::vector<Vec3> points(anchored ? m_points_per_frame : 0);
    std::vector<Affine> world_of(m_scene.objects.size());
    for (int f = 0; f <= m_scene.last_frame; ++f) {
        for (std::size_t i = 0; i < m_scene.objects.size(); ++i) {
            const std::optional<std::size_t> parent = m_scene.objects[i].parent;
            world_of[i] = parent ? world_of[*parent] * own_transform(i, f) : own_transform(i, f);
            if (boxes[i].empty())
                continue;
            const double reach = largest_coordinate(world_of[i], boxes[i]);
            if (std::isnan(reach) || reach > limit)
                return OutOfReach{i, f, reach};
        }
        if (!anchored)
            continue;
        frame(f, points);
        for (std::size_t i = 0; i < m_scene.objects.size(); ++i) {
            if (!m_anchors[i])
                continue;
            const ObjectPoints place = m_object_points[i];
            const double reach = largest_value(std::span<const Vec3>(points).subspan(place.first, place.count));
            if (std::isnan(reach) || reach > limit)
                return OutOfReach{i, f, reach, true};
        }
    }
    return std::nullopt;
}

std::vector<TimedWaypoint> timed_waypoints(const Scene& scene, const SceneAnimation& animation)
{
    std::vector<TimedWaypoint> waypoints;
    for (std::size_t index = 0; index < scene.objects.size(); ++index) {
        const SceneObject& object = scene.objects[index];
        if (!object.move)
            continue;
        const SceneMove& move = *object.move;
        for (std::size_t k = 0; k < move.times.size() && k < move.path.size(); ++k) {
            const int frame = move.times[k];
            const Vec3& point = move.path[k].position;
            waypoints.push_back({index, frame, object.parent ? animation.transform(*object.parent, frame)(point) : point});
        }
    }
    return waypoints;
}

} // namespace apcs
