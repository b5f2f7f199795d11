#pragma once

#include "apcs/formats/script_goal.h"
#include "apcs/session/session.h"

#include <string>
#include <string_view>

namespace apcs {

// How far a session is from a goal: whether it holds, the goal's quantity now ("+0.45" for a
// staff value, "0.35" for a distance; empty before there is one), that quantity in words ("tension
// +0.10"; "the curve passes 0.35 from (0.00, 1.00, 2.00)"; "no path is being shaped"), what the goal
// wants ("want +0.40 to +0.60") and, when the student is where no key can reach the goal, where to
// go ("you are on BIAS; the goal is TENSION: finish the staff, then Y").
struct GoalProgress {
    bool reached = false;
    std::string value;
    std::string said;
    std::string want;
    std::string hint;
    std::string said_briefly; // the quantity in a few words: "tension +0.10", "0.35 off"
};

// The goal checked against the path being shaped: VALUE against the staff of the region on it,
// NEAR against the sampled curve (the polyline through its samples, the distance to the nearest of
// its segments), INBETWEEN against the in-between's position. Outside the shaping of a path, or
// before a region is on the staff (VALUE), or with fewer in-betweens than K, a goal does not hold.
GoalProgress check_goal(const ScriptGoal& goal, const Session& session);

// A key changed the staff but left in-between K where it was (an INBETWEEN goal): the hint says
// why, "in-between 1 stayed 0.24 off: nearest spacing snaps it to a curve sample".
void explain_unmoved(GoalProgress& progress, const ScriptGoal& goal, const Session& session);

// "tension +0.10, want +0.40 to +0.60": how far off, for FILE:LINE: goal not reached and apcs.log.
std::string goal_distance_text(const GoalProgress& progress);

// The message line at a goal (SPEC §3.1): "GOAL: tension +0.10, want +0.40 to +0.60", or the hint
// instead when there is one ("GOAL: you are on BIAS; …"), or "GOAL REACHED:
// tension +0.45 (want +0.40 to +0.60)".
std::string goal_feedback(const GoalProgress& progress);

// The message line once a goal is left: "GOAL skipped: tension +0.00, want +0.40 to +0.60" (`verdict`
// "skipped"), the quantity in a few words ("GOAL not reached: 0.39 off, want within 0.10") when
// the whole does not fit the line.
std::string goal_verdict_line(std::string_view verdict, const GoalProgress& progress);

// The feedback in a few words, for beside "Adjust the path again ? (Y/N)" when the whole of it
// does not fit there: "GOAL: 0.35 off, want within 0.10", "GOAL REACHED: tension +0.45".
std::string goal_feedback_briefly(const GoalProgress& progress);

} // namespace apcs
