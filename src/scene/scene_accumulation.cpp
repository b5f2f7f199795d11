// SceneAnimation's T_f as Net_Anim's accumulation (SPEC §8.2), one tick a frame.
#include "apcs/scene/scene_animation.h"

#include "apcs/base/parallel_work.h"
#include "roll_turn.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

namespace apcs {

namespace {

Affine transposed(const Affine& rotation)
{
    Affine result;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            result.m[i][j] = rotation.m[j][i];
    return result;
}

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;

} // namespace

Vec3 SceneAnimation::move_offset(std::size_t index, int f) const
{
    const std::optional<std::size_t> step = move_step(index, f);
    return step ? m_move_offsets[index][*step] : Vec3{};
}

void SceneAnimation::accumulate()
{
    // An object's ticks are its own, except a ROLL's, which follow its parents' motion in the
    // world: the others on every core, then the ROLLs in file order (parents first).
    const std::size_t count = m_scene.objects.size();
    for_each_index_in_parallel(count, std::max(1u, std::thread::hardware_concurrency()), [this](std::size_t i) {
        if (m_scene.objects[i].accumulates() && !m_scene.objects[i].roll)
            accumulate_object(i);
    });
    for (std::size_t i = 0; i < count; ++i)
        if (m_scene.objects[i].roll)
            accumulate_object(i);
    // The ALIGN turns are in the states now.
    m_move_turns = {};
}

void SceneAnimation::accumulate_object(std::size_t index)
{
    std::vector<ActorState>& states = m_states[index];
    states.assign(frame_count(), ActorState{});
    for (int f = 1; f <= m_scene.last_frame; ++f) {
        const ActorState& before = states[static_cast<std::size_t>(f - 1)];
        std::vector<TickTurn> turns = tick_turns(index, f);
        const std::optional<TickScale> scale = tick_scale(index, f);
        if (m_scene.objects[index].roll)
            turns.push_back(roll_turn(index, f, before, turns, scale));
        states[static_cast<std::size_t>(f)] =
            turns.empty() && !scale ? before : tick(before, m_centres[index], turns, scale);
    }
}

std::vector<TickTurn> SceneAnimation::tick_turns(std::size_t index, int f) const
{
    const SceneObject& object = m_scene.objects[index];
    std::vector<TickTurn> turns;
    if (object.move && object.move->align) {
        const auto align_at = [&](int frame) {
            const std::optional<std::size_t> step = move_step(index, frame);
            return step ? linear_part(m_move_turns[index][*step]) : Affine{};
        };
        const Affine now = align_at(f);
        const Affine then = align_at(f - 1);
        if (now.m != then.m)
            turns.push_back({now * transposed(then), object.move->path.front().position});
    }
    if (object.rotate) {
        const SceneRotate& rotate = *object.rotate;
        const int frames = rotate.frames.elapsed(f) - rotate.frames.elapsed(f - 1);
        if (frames != 0 && rotate.degrees_per_frame != 0.0)
            turns.push_back({Affine::rotation_about(rotate.degrees_per_frame * frames, rotate.axis, Vec3{}),
                             rotate.about.value_or(m_centres[index])});
    }
    return turns;
}

std::optional<TickScale> SceneAnimation::tick_scale(std::size_t index, int f) const
{
    const std::optional<SceneScale>& scale = m_scene.objects[index].scale;
    if (!scale)
        return std::nullopt;
    const int frames = scale->frames.elapsed(f) - scale->frames.elapsed(f - 1);
    if (frames == 0)
        return std::nullopt;
    const Vec3 factors{std::pow(scale->factors.x, frames), std::pow(scale->factors.y, frames),
                       std::pow(scale->factors.z, frames)};
    return TickScale{factors, scale->about.value_or(m_centres[index])};
}

TickTurn SceneAnimation::roll_turn(std::size_t index, int f, const ActorState& before,
                                   std::span<const TickTurn> turns, const std::optional<TickScale>& scale) const
{
    const SceneObject& object = m_scene.objects[index];
    const SceneRoll& roll = *object.roll;
    const Vec3 hub = roll.about.value_or(m_centres[index]);
    const Affine parent_then = object.parent ? transform(*object.parent, f - 1) : Affine{};
    const Affine parent_now = object.parent ? transform(*object.parent, f) : Affine{};
    // Where the tick without the roll leaves the part: a turn about the hub does not move the hub
    // (with an ALIGN about another point in the same tick, to second order in the tick's angles).
    const ActorState others = tick(before, m_centres[index], turns, scale);
    const Affine world_then = parent_then * actor_transform(before, move_offset(index, f - 1));
    const Affine world_now = parent_now * actor_transform(others, move_offset(index, f));
    const RollPlane plane = roll_plane(roll.axis);
    const double distance = rolled_distance(plane, world_now(hub) - world_then(hub));
    const double others_turn = turn_in_plane(plane, world_now) - turn_in_plane(plane, world_then);
    const double radians = roll_step(distance, roll.radius, others_turn);
    return {Affine::rotation_about(radians * degrees_per_radian, roll.axis, Vec3{}), hub};
}

} // namespace apcs
