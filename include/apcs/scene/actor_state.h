#pragma once

#include "apcs/geometry/affine.h"
#include "apcs/geometry/vec3.h"

#include <optional>
#include <span>

namespace apcs {

// One turn of one tick (SPEC §8.2): a ROTATE's, an ALIGN's or a ROLL's change since the frame
// before. Only the linear part of `rotation` is used; `about` is the point it turns about, in the
// object's frame-0 coordinates.
struct TickTurn {
    Affine rotation;
    Vec3 about;
};

// One SCALE's change since the frame before: a factor per axis of the scene about `about` (frame-0
// coordinates).
struct TickScale {
    Vec3 factors{1.0, 1.0, 1.0};
    Vec3 about;
};

// Net_Anim's state of an object between ticks (seed 003 §2.1, ACTSTATE), its MOVE's offset and its
// parents left out: the map U with U(p) = body·(p − centre) + centre + drift, `centre` the middle
// of the object's frame-0 drawing, body (turn × scale) its linear part and drift how far the turns
// and scales about other points have carried its centre. Frame 0's state is the identity, exactly.
// The MOVE's offset is added apart (actor_transform), so a MOVE alone stays exact.
using ActorState = Affine;

// The state one tick later (SPEC §8.2; seed 003 §2.2 (1) and (3)): every change is computed from
// `before` and summed, none sees another's. A turn by R about a point at offset r from the centre
// moves the centre by (R − I)(−r), a scale by F about a point at offset s by (1 − F)·s, r and s
// being the points' frame-0 offsets carried with the body (turned and scaled with it); then the
// body turns and scales about its centre by turns[0]·turns[1]·…·scale (the first turn outermost).
// Axes are the scene's (the parent's coordinates): a turn's axis is not carried by the body.
ActorState tick(const ActorState& before, const Vec3& centre, std::span<const TickTurn> turns,
                const std::optional<TickScale>& scale);

// The map's linear part (no translation).
Affine linear_part(const Affine& map);

// T_f of an object in its parent's coordinates: its state with its MOVE's offset P(s(f)) − P_0.
Affine actor_transform(const ActorState& state, const Vec3& move_offset);

} // namespace apcs
