#include "apcs/scene/actor_state.h"

namespace apcs {

namespace {

Vec3 scaled(const Vec3& factors, const Vec3& v) { return {factors.x * v.x, factors.y * v.y, factors.z * v.z}; }

} // namespace

Affine linear_part(const Affine& map)
{
    Affine linear = map;
    linear.t = Vec3{};
    return linear;
}

ActorState tick(const ActorState& before, const Vec3& centre, std::span<const TickTurn> turns,
                const std::optional<TickScale>& scale)
{
    const Affine body = linear_part(before);
    Vec3 shift;
    Affine change;
    for (const TickTurn& turn : turns) {
        const Affine rotation = linear_part(turn.rotation);
        const Vec3 offset = body(turn.about - centre);
        shift += rotation(-offset) + offset;
        change = change * rotation;
    }
    if (scale) {
        const Vec3 offset = body(scale->about - centre);
        shift += offset - scaled(scale->factors, offset);
        change = change * Affine::scale_about(scale->factors, Vec3{});
    }
    const Affine next_body = change * body;
    ActorState next = next_body;
    // U(p) = body·p + (centre − body·centre + drift): a tick that changes nothing adds exactly 0.
    next.t = before.t + (shift + (body(centre) - next_body(centre)));
    return next;
}

Affine actor_transform(const ActorState& state, const Vec3& move_offset)
{
    Affine transform = state;
    transform.t = state.t + move_offset;
    return transform;
}

} // namespace apcs
