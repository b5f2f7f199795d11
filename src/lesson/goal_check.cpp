#include "apcs/lesson/goal_check.h"

#include "apcs/editor/path_editor.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace apcs {

namespace {

// "+0.10" with `sign`, "0.35" without.
enum class Sign { shown, left_out };
std::string number_text(double value, Sign sign)
{
    char text[48];
    if (sign == Sign::shown)
        std::snprintf(text, sizeof text, "%+.2f", value);
    else
        std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

// The distance from `point` to the segment from `from` to `to`.
double segment_distance(const Vec3& point, const Vec3& from, const Vec3& to)
{
    const Vec3 along = to - from;
    const double squared = dot(along, along);
    const double fraction = squared > 0 ? std::clamp(dot(point - from, along) / squared, 0.0, 1.0) : 0.0;
    return distance(point, from + along * fraction);
}

double curve_distance(const Vec3& point, const std::vector<Vec3>& samples)
{
    if (samples.size() == 1)
        return distance(point, samples.front());
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t index = 1; index < samples.size(); ++index)
        nearest = std::min(nearest, segment_distance(point, samples[index - 1], samples[index]));
    return nearest;
}

GoalProgress value_progress(const ScriptGoal& goal, const PathEditor& editor)
{
    const std::optional<StaffValues> staff = editor.region_staff();
    if (!staff)
        return {false, "no region is on the staff, want " + goal_text(goal)};
    const double value = (*staff)[goal.line];
    // The staff's values are multiples of the step, snapped: a bound met to 1e-9 is met.
    constexpr double slack = 1e-9;
    const bool reached = value >= goal.low - slack && value <= goal.high + slack;
    std::string said = goal_text(goal);
    said = said.substr(0, said.find(" within ")) + " " + number_text(value, Sign::shown);
    return {reached, said + (reached ? ": goal reached" : ", want " + number_text(goal.low, Sign::shown) + " to " +
                                                             number_text(goal.high, Sign::shown))};
}

GoalProgress distance_progress(const ScriptGoal& goal, const PathEditor& editor)
{
    const EvaluatedPath& path = editor.evaluated();
    double off = 0.0;
    std::string what;
    if (goal.kind == ScriptGoal::Kind::near) {
        off = curve_distance(goal.point, path.curve.samples());
        what = "the curve passes ";
    } else {
        if (goal.inbetween > path.inbetweens.size())
            return {false, "the path has " + std::to_string(path.inbetweens.size()) + " in-betweens, want " +
                               goal_text(goal)};
        off = distance(goal.point, path.inbetweens[goal.inbetween - 1].position);
        what = "in-between " + std::to_string(goal.inbetween) + " is ";
    }
    const std::string target = goal_text(goal);
    const std::string where = target.substr(target.find(" of (") + 4);
    const bool reached = off <= goal.within;
    return {reached, what + number_text(off, Sign::left_out) + " from " + where +
                         (reached ? ": goal reached" : ", want within " + number_text(goal.within, Sign::left_out))};
}

} // namespace

GoalProgress check_goal(const ScriptGoal& goal, const Session& session)
{
    const PathEditor* editor = session.path_editor();
    if (editor == nullptr)
        return {false, "no path is being shaped, want " + goal_text(goal)};
    return goal.kind == ScriptGoal::Kind::value ? value_progress(goal, *editor) : distance_progress(goal, *editor);
}

} // namespace apcs
