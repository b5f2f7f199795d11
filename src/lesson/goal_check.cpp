#include "apcs/lesson/goal_check.h"

#include "apcs/editor/path_editor.h"
#include "apcs/formats/text_fields.h"

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

// The distance from `point` to the curve's polyline, and the segment (between control points s and
// s + 1) where it comes nearest.
struct CurveNearest {
    double distance = std::numeric_limits<double>::infinity();
    std::size_t segment = 0;
};
CurveNearest curve_nearest(const Vec3& point, const SampledCurve& curve)
{
    const std::size_t count = curve.sample_count();
    if (count == 1)
        return {distance(point, curve.sample(0)), 0};
    CurveNearest nearest;
    const auto per_segment = static_cast<std::size_t>(std::max(curve.samples_per_segment, 1));
    Vec3 before = count > 0 ? curve.sample(0) : Vec3{};
    for (std::size_t index = 1; index < count; ++index) {
        const Vec3 after = curve.sample(index);
        const double off = segment_distance(point, before, after);
        before = after;
        if (off < nearest.distance)
            nearest = {off, (index - 1) / per_segment};
    }
    return nearest;
}

std::string upper_name(StaffLine line) { return std::string(staff_line_name(line)); }

// Where the student stands when no key there reaches a VALUE goal: another staff line. (At the
// question after the staff the question comes first on the message line, the goal beside it.)
std::string value_hint(const ScriptGoal& goal, const PathEditor& editor)
{
    const std::optional<StaffLine> line = editor.staff_line();
    if (!line || *line == goal.line)
        return {};
    const std::string where = "you are on " + upper_name(*line) + "; the goal is " + upper_name(goal.line);
    return where + (*line < goal.line ? ": Enter or Esc goes down a line" : ": finish the staff, then Y");
}

GoalProgress value_progress(const ScriptGoal& goal, const PathEditor& editor)
{
    const std::string want = "want " + number_text(goal.low, Sign::shown) + " to " + number_text(goal.high, Sign::shown);
    const std::optional<StaffValues> staff = editor.region_staff();
    if (!staff)
        return {false, {}, "no region is on the staff", want, "8 puts the whole path on the staff, 2 a region",
                "no region"};
    const double value = (*staff)[goal.line];
    // The staff's values are multiples of the step, snapped: a bound met to 1e-9 is met.
    constexpr double slack = 1e-9;
    const bool reached = value >= goal.low - slack && value <= goal.high + slack;
    const std::string shown = number_text(value, Sign::shown);
    const std::string said = ascii_lower_case(staff_line_name(goal.line)) + " " + shown;
    return {reached, shown, said, want, reached ? std::string() : value_hint(goal, editor), said};
}

// A NEAR goal's span outside the region on the staff: no staff key there moves it.
std::string region_hint(std::size_t segment, const PathEditor& editor)
{
    if (!editor.staff_line())
        return {};
    const std::optional<ControlRegion> region = editor.region();
    // The values of control point k shape the spans on either side of it: k - 1 to k, k to k + 1.
    if (!region || (segment + 1 >= region->first && segment <= region->last))
        return {};
    return "the region (points " + std::to_string(region->first + 1) + " to " + std::to_string(region->last + 1) +
           ") cannot move span " + std::to_string(segment + 1) + " to " + std::to_string(segment + 2) +
           ", nearest the goal";
}

GoalProgress distance_progress(const ScriptGoal& goal, const PathEditor& editor)
{
    const EvaluatedPath& path = editor.evaluated();
    const std::string want = "want within " + number_text(goal.within, Sign::left_out);
    const std::string target = goal_text(goal);
    const std::string where = target.substr(target.find(" of (") + 4);
    if (goal.kind == ScriptGoal::Kind::near) {
        const CurveNearest nearest = curve_nearest(goal.point, path.curve);
        const std::string off = number_text(nearest.distance, Sign::left_out);
        const bool reached = nearest.distance <= goal.within;
        return {reached, off, "the curve passes " + off + " from " + where, want,
                reached ? std::string() : region_hint(nearest.segment, editor), off + " off"};
    }
    if (goal.inbetween > path.inbetweens.size())
        return {false, {}, "the path has " + std::to_string(path.inbetweens.size()) + " in-betweens",
                "want " + goal_text(goal), {}, std::to_string(path.inbetweens.size()) + " in-betweens"};
    const double distance_now = distance(goal.point, path.inbetweens[goal.inbetween - 1].position);
    const std::string off = number_text(distance_now, Sign::left_out);
    return {distance_now <= goal.within, off,
            "in-between " + std::to_string(goal.inbetween) + " is " + off + " from " + where, want, {}, off + " off"};
}

} // namespace

GoalProgress check_goal(const ScriptGoal& goal, const Session& session)
{
    const PathEditor* editor = session.path_editor();
    if (editor == nullptr)
        return {false, {}, "no path is being shaped", "want " + goal_text(goal),
                "no path is being shaped: the goal waits for one", "no path"};
    return goal.kind == ScriptGoal::Kind::value ? value_progress(goal, *editor) : distance_progress(goal, *editor);
}

void explain_unmoved(GoalProgress& progress, const ScriptGoal& goal, const Session& session)
{
    const PathEditor* editor = session.path_editor();
    if (goal.kind != ScriptGoal::Kind::inbetween || editor == nullptr || progress.value.empty())
        return;
    const std::string stayed = "in-between " + std::to_string(goal.inbetween) + " stayed " + progress.value + " off: ";
    // Nearest spacing puts each in-between on the curve sample nearest its target (SPEC §4.3): a
    // step smaller than a sample's share of the path moves the target, not the sample.
    progress.hint = stayed + (editor->settings().spacing == Spacing::nearest
                                  ? "nearest spacing snaps it to a curve sample"
                                  : "the key changed no span it lies in");
}

std::string goal_distance_text(const GoalProgress& progress) { return progress.said + ", " + progress.want; }

std::string goal_feedback(const GoalProgress& progress)
{
    if (progress.reached)
        return "GOAL REACHED: " + progress.said + " (" + progress.want + ")";
    if (!progress.hint.empty())
        return "GOAL: " + progress.hint;
    return "GOAL: " + goal_distance_text(progress);
}

std::string goal_verdict_line(std::string_view verdict, const GoalProgress& progress)
{
    const std::string whole = "GOAL " + std::string(verdict) + ": " + goal_distance_text(progress);
    if (fits_message_line(whole))
        return whole;
    return "GOAL " + std::string(verdict) + ": " + progress.said_briefly + ", " + progress.want;
}

std::string goal_feedback_briefly(const GoalProgress& progress)
{
    if (progress.reached)
        return "GOAL REACHED: " + progress.said_briefly;
    return "GOAL: " + progress.said_briefly + ", " + progress.want;
}

} // namespace apcs
