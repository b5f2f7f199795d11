#pragma once

#include "apcs/formats/script_goal.h"
#include "apcs/session/session.h"

#include <string>

namespace apcs {

// How far a session is from a goal: whether it holds, and in words how far off it is ("tension
// +0.10, want +0.40 to +0.60"; "the curve passes 0.35 from (0.00, 1.00, 2.00), want within 0.10";
// "no path is being shaped, want tension within +0.40 to +0.60").
struct GoalProgress {
    bool reached = false;
    std::string said;
};

// The goal checked against the path being shaped: VALUE against the staff of the region on it,
// NEAR against the sampled curve (the polyline through its samples, the distance to the nearest of
// its segments), INBETWEEN against the in-between's position. Outside the shaping of a path, or
// before a region is on the staff (VALUE), or with fewer in-betweens than K, a goal does not hold.
GoalProgress check_goal(const ScriptGoal& goal, const Session& session);

} // namespace apcs
