#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/base/diagnostic.h"
#include "apcs/geometry/vec3.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// An exercise's goal, a GOAL line of a key script (SPEC §3), in world units:
//   GOAL VALUE NAME LO HI         the staff line NAME (TENSION, CONTINUITY, BIAS, ACCELERATION, any
//                                 case) of the region on the staff within [LO, HI]
//   GOAL NEAR X Y Z D             the curve of the path being shaped passes within D of (X, Y, Z)
//   GOAL INBETWEEN K X Y Z D      in-between K (1 … M) of that path within D of (X, Y, Z)
// Its answer is the keys that follow it up to the next caption, GOAL line or the end of the
// script: a headless replay plays them (the goal is judged as replay_driver.h says: on its path as
// accepted, else at the next GOAL line or the end); a replay on a terminal stops at the goal, the
// student reaches it live, and the answer's keys are skipped.
struct ScriptGoal {
    enum class Kind { value, near, inbetween };
    Kind kind = Kind::value;
    StaffLine line = StaffLine::tension; // VALUE
    double low = 0.0;                    // VALUE: the range, low <= high
    double high = 0.0;
    Vec3 point;             // NEAR, INBETWEEN
    double within = 0.0;    // NEAR, INBETWEEN: D > 0
    std::size_t inbetween = 0; // INBETWEEN: K >= 1
    std::size_t before_event = 0; // the keys played before it
    std::size_t answer_end = 0;   // the first key after its answer
    int line_number = 0;          // where the script has it, for FILE:LINE
    // The script's captions before the GOAL line: the last of them is the task, shown while the
    // goal waits (a caption right after the line, at the same key, closes the exercise).
    std::size_t captions_before = 0;
    bool operator==(const ScriptGoal&) const = default;
};

// The goal of a line that starts with "GOAL " (the words after it, blank-separated; a ';' comment
// may follow), or "FILE:LINE: expected GOAL VALUE NAME LO HI, GOAL NEAR X Y Z D or GOAL INBETWEEN
// K X Y Z D; found …" and a reason. before_event and answer_end are left to the caller.
[[nodiscard]] Expected<ScriptGoal> parse_goal_line(std::string_view words, const std::string& file_name,
                                                   int line_number);

// ok when every INBETWEEN goal's K is at most `inbetween_count`, the in-betweens the session makes
// (--inbetweens); else "FILE:LINE: GOAL INBETWEEN 13 names an in-between beyond the 12 the
// session makes (--inbetweens 12); expected K from 1 to 12": a goal nobody can reach.
[[nodiscard]] Expected<void> goals_within_inbetweens(const std::vector<ScriptGoal>& goals, std::size_t inbetween_count,
                                                     const std::string& file_name);

// The GOAL line parse_goal_line reads back to the same goal: "GOAL VALUE TENSION 0.4 0.6",
// "GOAL NEAR 0 1 2 0.1", "GOAL INBETWEEN 1 0.31 -0.41 0.47 0.1" (shortest numbers).
std::string goal_line(const ScriptGoal& goal);

// The point a NEAR or INBETWEEN goal names, to be marked on screen; none for VALUE.
std::optional<Vec3> goal_point(const ScriptGoal& goal);

// "tension within +0.40 to +0.60", "the curve within 0.10 of (0.00, 1.00, 2.00)", "in-between 3
// within 0.10 of (…)": the goal in words, for messages.
std::string goal_text(const ScriptGoal& goal);

} // namespace apcs
